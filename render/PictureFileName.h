// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace rs::render {

// Whether writeNetworkPicture can write a file of this name: it ends in .svg
// or .png, in any case.
bool isPictureFileName(const QString& path);

} // namespace rs::render
