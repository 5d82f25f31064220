#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the Debian package from a build tree and checks it as Debian's tools
# and a user would: fields, file list, lintian, the desktop, AppStream and MIME
# files, the man pages, and the unpacked programs themselves.
#   check-package.sh BUILD_DIR CPACK SOURCE_DIR
set -euo pipefail

build=$1
cpack=$2
source=$3
app_id=io.github.rungsmith.Rungsmith
scratch=$build/tests/package-check
root=$scratch/root
failures=0

fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

# Runs a command; on failure shows its output and counts it.
expect_success() {
    local what=$1
    shift
    local output
    if ! output=$("$@" 2>&1); then
        fail "$what"
        printf '%s\n' "$output" >&2
    fi
}

rm -rf "$scratch"
mkdir -p "$root"

if ! "$cpack" --config "$build/CPackConfig.cmake" -B "$scratch" >"$scratch/cpack.log" 2>&1; then
    cat "$scratch/cpack.log" >&2
    echo "FAIL: cpack could not build the package" >&2
    exit 1
fi
debs=("$scratch"/rungsmith_*.deb)
deb=${debs[0]}
if [ ! -f "$deb" ]; then
    cat "$scratch/cpack.log" >&2
    echo "FAIL: cpack made no rungsmith_*.deb in $scratch" >&2
    exit 1
fi
echo "built $(basename "$deb")"

# Control fields.
version=$(cat "$build/generated/version.txt")
field() { dpkg-deb --field "$deb" "$1"; }
[ "$(field Package)" = rungsmith ] || fail "Package is '$(field Package)'"
[ "$(field Version)" = "$version" ] || fail "Version is '$(field Version)', the build's is '$version'"
# A development build names its commit.
if revision=$(git -C "$source" rev-parse --short HEAD 2>/dev/null) &&
    ! git -C "$source" describe --exact-match --match 'v*' HEAD >/dev/null 2>&1; then
    [[ "$version" =~ ^[0-9.]+~git[0-9]{8}\.$revision$ ]] ||
        fail "the version $version does not name the commit $revision (build again after a commit)"
fi
[ "$(field Section)" = electronics ] || fail "Section is '$(field Section)'"
[[ "$(field Maintainer)" =~ ^[^\<]+\ \<[^@]+@[^\>]+\>$ ]] || fail "Maintainer is '$(field Maintainer)'"
# shlibdeps found the Qt libraries the programs link.
for library in libqt6core6 libqt6gui6 libqt6widgets6 libqt6svg6 libqscintilla2-qt6-15 libc6; do
    [[ ",$(field Depends)," =~ [\ ,]${library}[\ ,\(] ]] || fail "Depends lacks $library: $(field Depends)"
done
[ "$(field Description | wc -l)" -ge 5 ] || fail "Description has no real long part"

# The file list.
listing=$(dpkg-deb --contents "$deb" | awk '{print $6}')
for path in \
    ./usr/bin/rungsmith \
    ./usr/bin/rungsmith-cli \
    ./usr/libexec/rungsmith/rungsmith-drawing.so \
    ./usr/share/rungsmith/examples/muting.sps \
    ./usr/share/rungsmith/examples/muting.prop \
    ./usr/share/rungsmith/examples/estop.sps \
    ./usr/share/rungsmith/examples/estop.prop \
    ./usr/share/rungsmith/examples/two-hand.prop \
    ./usr/share/rungsmith/examples/muting-wrong.prop \
    ./usr/share/rungsmith/examples/press-line.sps \
    ./usr/share/rungsmith/examples/safety-cell.sps \
    ./usr/share/rungsmith/examples/safety-cell-press.scn \
    ./usr/share/rungsmith/examples/safety-cell-conveyor.scn \
    ./usr/share/rungsmith/libraries/Analog01.rslib \
    ./usr/share/rungsmith/libraries/Rungsmith_Basics.rslib \
    ./usr/share/rungsmith/libraries/Rungsmith_Speed.rslib \
    ./usr/share/rungsmith/libraries/Rungsmith_System.rslib \
    ./usr/share/rungsmith/libraries/Rungsmith_Safety.rslib \
    ./usr/share/rungsmith/libraries/Rungsmith_Safety/SF_EmergencyStop.sps \
    ./usr/share/rungsmith/libraries/Rungsmith_Safety/SF_EmergencyStop.scn \
    "./usr/share/applications/$app_id.desktop" \
    "./usr/share/metainfo/$app_id.metainfo.xml" \
    ./usr/share/mime/packages/rungsmith.xml \
    "./usr/share/icons/hicolor/scalable/apps/$app_id.svg" \
    ./usr/share/icons/hicolor/scalable/mimetypes/text-x-pluto-project.svg \
    ./usr/share/icons/hicolor/scalable/mimetypes/application-x-pluto-image.svg \
    ./usr/share/icons/hicolor/scalable/mimetypes/text-x-rungsmith-scenario.svg \
    ./usr/share/man/man1/rungsmith.1.gz \
    ./usr/share/man/man1/rungsmith-cli.1.gz \
    ./usr/share/doc/rungsmith/copyright \
    ./usr/share/doc/rungsmith/changelog.gz; do
    grep -qxF "$path" <<<"$listing" || fail "the package lacks $path"
done

# Debian's policy checker: errors fail, warnings are shown.
lintian --fail-on error --tag-display-limit 0 "$deb" >"$scratch/lintian.log" 2>&1 ||
    fail "lintian reports errors"
cat "$scratch/lintian.log"

dpkg-deb --extract "$deb" "$root"
share=$root/usr/share

expect_success "desktop-file-validate" desktop-file-validate "$share/applications/$app_id.desktop"
expect_success "appstreamcli validate" appstreamcli validate --no-net "$share/metainfo/$app_id.metainfo.xml"
# The icon the desktop entry and AppStream name is the one installed.
grep -qx "Icon=$app_id" "$share/applications/$app_id.desktop" || fail "the desktop entry names another icon"

# The MIME database built from the package's entry knows the three file types.
cp -r "$share/mime" "$scratch/mime"
expect_success "update-mime-database" update-mime-database "$scratch/mime"
for glob in text/x-pluto-project:\*.sps application/x-pluto-image:\*.hps \
    text/x-rungsmith-scenario:\*.scn; do
    grep -qxF "50:$glob" "$scratch/mime/globs2" || fail "the MIME database lacks $glob"
done
grep -q '^MimeType=text/x-pluto-project;$' "$share/applications/$app_id.desktop" ||
    fail "the desktop entry does not open projects"

# The unpacked programs run on the system's Qt, without LD_LIBRARY_PATH.
cli=$root/usr/bin/rungsmith-cli
mkdir -p "$scratch/files"
check_output=$(env -u LD_LIBRARY_PATH "$cli" check "$share/rungsmith/examples/muting.sps" 2>&1) ||
    fail "rungsmith-cli check on the bundled example: $check_output"
grep -q "0 Error(s) detected Result=OK" <<<"$check_output" || fail "check printed: $check_output"
"$cli" compile "$share/rungsmith/examples/muting.sps" -o "$scratch/files/muting.hps" >/dev/null ||
    fail "rungsmith-cli compile on the bundled example"
# The prover (CaDiCaL linked in) proves the bundled example's properties.
prove_output=$(env -u LD_LIBRARY_PATH "$cli" prove "$share/rungsmith/examples/estop.sps" \
    "$share/rungsmith/examples/estop.prop" --cex "$scratch/files" 2>&1) ||
    fail "rungsmith-cli prove on the bundled example: $prove_output"
grep -q "^5 proved, 0 failed, 0 unknown$" <<<"$prove_output" || fail "prove printed: $prove_output"
# The drawing module is found from the program's own place too, and the
# command line draws with it.
ladder_output=$(env -u LD_LIBRARY_PATH "$cli" ladder "$share/rungsmith/examples/muting.sps" \
    --unit 0 --network 1 -o "$scratch/files/muting.svg" 2>&1) ||
    fail "rungsmith-cli ladder on the bundled example: $ladder_output"
grep -q "<svg" "$scratch/files/muting.svg" || fail "rungsmith-cli ladder wrote no SVG"
# The standard libraries are found from the program's own place, wherever
# the package is unpacked.
# (Read whole first: grep -q stops at the first match, and the list, long
# enough to be written still, would die of SIGPIPE under pipefail.)
blocks_output=$(env -u LD_LIBRARY_PATH "$cli" blocks list) ||
    fail "rungsmith-cli blocks list failed"
grep -q "^Rungsmith_Basics ResetLatch(" <<<"$blocks_output" ||
    fail "rungsmith-cli blocks list does not find the standard library"
[ "$("$cli" --version)" = "rungsmith-cli $version" ] || fail "rungsmith-cli --version: $("$cli" --version)"
gui_version=$(QT_QPA_PLATFORM=offscreen "$root/usr/bin/rungsmith" --version 2>/dev/null) || true
[ "$gui_version" = "rungsmith $version" ] || fail "rungsmith --version: $gui_version"
file "$cli" "$root/usr/bin/rungsmith" "$root/usr/libexec/rungsmith/rungsmith-drawing.so" |
    grep -v ', stripped' && fail "unstripped programs"

# A file manager (GLib's detection) sees each file as its type, and Godot's
# scenes, which share *.scn, still as theirs.
cp "$share/rungsmith/examples/muting.sps" "$scratch/files/"
printf '; stop drops the output\nset I0.0 1\nrun 20ms\nexpect Q0.0 0\n' >"$scratch/files/stop.scn"
printf '[gd_scene load_steps=2 format=3]\n' >"$scratch/files/level.scn"
content_type() {
    XDG_DATA_DIRS=$scratch:/usr/share gio info --attributes=standard::content-type "$1" |
        sed -n 's/^ *standard::content-type: //p'
}

for expected in muting.sps:text/x-pluto-project muting.hps:application/x-pluto-image \
    stop.scn:text/x-rungsmith-scenario level.scn:application/x-godot-scene; do
    name=${expected%%:*}
    type=$(content_type "$scratch/files/$name")
    [ "$type" = "${expected#*:}" ] || fail "$name is seen as '$type', not ${expected#*:}"
done

# The man pages list every verb and option of the command-line contract
# (../shared/spec/cli.md) and of the IDE.
man_text() { gzip -dc "$share/man/man1/$1.1.gz" | groff -man -Tutf8 -P-cbou 2>&1; }
cli_page=$(man_text rungsmith-cli)
for word in check compile format test 'vars export' 'vars import' ladder roundtrip \
    --output --vcd --unit --sequence --step --network --scenario --no-io-warnings --help --version \
    'blocks list' 'blocks show' --lib --language 'EXIT STATUS'; do
    grep -qF -- "$word" <<<"$cli_page" || fail "the rungsmith-cli man page lacks '$word'"
done
gui_page=$(man_text rungsmith)
for word in --screenshot --page ladder:N text:N io:N variables:N --simulate --theme --help --version \
    FILE.sps; do
    grep -qF -- "$word" <<<"$gui_page" || fail "the rungsmith man page lacks '$word'"
done
for program in rungsmith-cli rungsmith; do
    page=$(gzip -dc "$share/man/man1/$program.1.gz")
    grep -q "^\.TH .*\"$program $version\"" <<<"$page" ||
        fail "the $program man page does not carry the version $version"
done

if [ "$failures" -gt 0 ]; then
    echo "$failures check(s) of $(basename "$deb") failed" >&2
    exit 1
fi
echo "$(basename "$deb"): every check passed"
