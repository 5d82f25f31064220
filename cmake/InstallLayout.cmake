# SPDX-License-Identifier: GPL-3.0-or-later
# Where `cmake --install` puts things (GNU layout: bin/, share/, share/man/),
# and with Debian's modes for the directories it makes, whatever the
# builder's umask. Included before any install() rule.
include(GNUInstallDirs)
set(CMAKE_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
    OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
