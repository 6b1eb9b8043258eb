#!/usr/bin/env bash
# Stages the Yak packages of the Grasshopper plugin, one per Rhino version, for one platform:
#   DIST/rh7-PLATFORM/  manifest.yml, icon.png and the net48 build          (Rhino 7, .NET Framework 4.8)
#   DIST/rh8-PLATFORM/  manifest.yml, icon.png, net48/ and net7.0/ folders  (Rhino 8: .NET 7 or .NET Framework mode)
# and, when a Yak executable is given, runs `yak build --platform PLATFORM` in each (Yak appends the
# distribution tag, e.g. lamella-0.1.0-rh7_13-win.yak, from the RhinoCommon version the .gha was built against).
# Each build folder must hold Lamella.Grasshopper.gha, Lamella.dll and the platform's native library under
# its packaged name (lamella_native.dll on Windows, liblamella_native.dylib on macOS; see csharp/README.md):
# cargo's lamella.dll would be the same file as Lamella.dll on Windows.
#
# Usage: csharp/package-yak.sh win|mac BUILD_DIR DIST_DIR [YAK]
#   BUILD_DIR  the project's output folder with net48/ and net7.0/ (csharp/Lamella.Grasshopper/bin/Release)
#   DIST_DIR   created; must not exist
#   YAK        e.g. "C:\Program Files\Rhino 8\System\Yak.exe" or /Applications/Rhino\ 8.app/Contents/Resources/bin/yak
set -euo pipefail

if [ $# -lt 3 ] || [ $# -gt 4 ]; then
    sed -n '2,15p' "$0" >&2
    exit 2
fi
platform=$1 build=$2 dist=$3 yak=${4:-}
here="$(cd "$(dirname "$0")" && pwd)"
case "$platform" in
    win) native=lamella_native.dll ;;
    mac) native=liblamella_native.dylib ;;
    *) echo "platform must be win or mac, not '$platform'" >&2; exit 2 ;;
esac
if [ -e "$dist" ]; then
    echo "$dist exists; give a new folder" >&2
    exit 2
fi

check() { # a build folder holds the plugin, the binding and the native library under its packaged name
    local folder=$1 file
    for file in Lamella.Grasshopper.gha Lamella.dll "$native"; do
        [ -f "$folder/$file" ] || { echo "$folder has no $file (build it first, see csharp/README.md)" >&2; exit 1; }
    done
}
check "$build/net48"
check "$build/net7.0"

top() { # the manifest and the icon at the top of a package; Yak wants no other manifest (the build copies one next to the .gha)
    find "$1" -mindepth 2 -name manifest.yml -delete
    cp "$here/Lamella.Grasshopper/manifest.yml" "$1/manifest.yml"
    cp "$here/Lamella.Grasshopper/Icons/Lamella.png" "$1/icon.png"
}
mkdir -p "$dist/rh7-$platform" "$dist/rh8-$platform"
cp -R "$build/net48/." "$dist/rh7-$platform/"
cp -R "$build/net48" "$build/net7.0" "$dist/rh8-$platform/"
top "$dist/rh7-$platform"
top "$dist/rh8-$platform"

for package in "$dist/rh7-$platform" "$dist/rh8-$platform"; do
    echo "staged $package"
    if [ -n "$yak" ]; then
        (cd "$package" && "$yak" build --platform "$platform")
    fi
done
