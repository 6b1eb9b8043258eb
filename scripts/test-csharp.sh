#!/usr/bin/env bash
# Checks the C# layer (csharp/) on Linux under Mono: builds the Rust library, the binding
# (csharp/Lamella), its NUnit tests (csharp/Lamella.Tests) and the Grasshopper plugin
# (csharp/Lamella.Grasshopper, compiled against the compile-only facades of csharp/facades), all with
# `mcs -sdk:4.8-api -warnaserror+`; checks that every Grasshopper/RhinoCommon/GH_IO member the built
# plugin references or overrides is verified against the real SDK (csharp/facades/check) and that the
# plugin's version matches the Yak manifest; then runs the tests against the real library, copied as
# liblamella_native.so (the name the binding imports, see csharp/README.md). Everything is built under
# target/csharp/. The last line is "N passed, N failed"; the exit status is non-zero on any failure.
# Needs cargo and python3; installs mono-devel, mono-utils (monodis) and NUnit 2.6 with apt-get (as root)
# when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"

target="${CARGO_TARGET_DIR:-target}"
build="$target/csharp"
facades="$build/facades"

missing=()
# mono-devel brings mcs and the .NET Framework 4.8 reference assemblies (mcs alone comes from mono-mcs).
{ command -v mcs >/dev/null && [ -f /usr/lib/mono/4.8-api/mscorlib.dll ]; } || missing+=(mono-devel)
command -v monodis >/dev/null || missing+=(mono-utils)
command -v nunit-console >/dev/null || missing+=(nunit-console)
[ -f /usr/lib/pkgconfig/nunit.pc ] || missing+=(libnunit-cil-dev)
if ((${#missing[@]})); then
    echo "== C#: installing ${missing[*]}"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi

echo "== C#: native library"
# With --tests: the build `cargo test` made (dev-dependencies unify the dependencies' features;
# a plain `cargo build --lib` would rebuild every dependency for the other feature set).
cargo build --locked --lib --tests

mkdir -p "$build" "$facades"
mcs=(mcs -sdk:4.8-api -langversion:7.2 -warnaserror+ -nologo -target:library)

echo "== C#: binding"
"${mcs[@]}" -out:"$build/Lamella.dll" -recurse:'csharp/Lamella/*.cs'

echo "== C#: Grasshopper plugin against the compile-only facades"
"${mcs[@]}" -r:System.Drawing.dll -out:"$facades/RhinoCommon.dll" -recurse:'csharp/facades/RhinoCommon/*.cs'
"${mcs[@]}" -out:"$facades/GH_IO.dll" -recurse:'csharp/facades/GH_IO/*.cs'
"${mcs[@]}" -r:System.Drawing.dll -r:"$facades/RhinoCommon.dll" -r:"$facades/GH_IO.dll" \
    -out:"$facades/Grasshopper.dll" -recurse:'csharp/facades/Grasshopper/*.cs'
icons=()
for icon in csharp/Lamella.Grasshopper/Icons/*.png; do
    icons+=("-resource:$icon,Lamella.Grasshopper.Icons.$(basename "$icon")")
done
# The facades stay in their own folder: nothing but this compile step ever sees them.
"${mcs[@]}" -r:System.Drawing.dll -r:"$facades/RhinoCommon.dll" -r:"$facades/GH_IO.dll" -r:"$facades/Grasshopper.dll" \
    -r:"$build/Lamella.dll" "${icons[@]}" -out:"$build/Lamella.Grasshopper.gha" -recurse:'csharp/Lamella.Grasshopper/*.cs'

echo "== C#: the plugin's SDK references against the members verified in the real assemblies"
check=csharp/facades/check
mcs -sdk:4.8-api -langversion:7.2 -warnaserror+ -nologo -target:exe -out:"$facades/MemberTool.exe" "$check/MemberTool.cs"
members=(python3 "$check/check_members.py" "$build/Lamella.Grasshopper.gha" "$facades" "$facades/MemberTool.exe" "$check/grasshopper-members.txt")
"${members[@]}" "$check/verified-members.txt"
# The check itself must be able to fail: without the verified list, members the plugin uses are unverified.
if "${members[@]}" /dev/null >/dev/null; then
    echo "the member check passed without verified-members.txt: it checks nothing"
    exit 1
fi
manifest_version=$(sed -n 's/^version: *//p' csharp/Lamella.Grasshopper/manifest.yml)
plugin_version=$(sed -n 's/.*AssemblyInformationalVersion("\(.*\)").*/\1/p' csharp/Lamella.Grasshopper/AssemblyInfo.cs)
if [ -z "$manifest_version" ] || [ "$manifest_version" != "$plugin_version" ]; then
    echo "manifest.yml version '$manifest_version' differs from the plugin's AssemblyInformationalVersion '$plugin_version' (Yak package restore needs them equal)"
    exit 1
fi

# The binding imports "lamella_native" (cargo's liblamella.so under the packaged name).
cp "$target/debug/liblamella.so" "$build/liblamella_native.so"
echo "== C#: Yak package layout (csharp/package-yak.sh on stand-in build folders)"
yak="$build/yak-layout"
rm -rf "$yak"
for framework in net48 net7.0; do
    mkdir -p "$yak/bin/$framework"
    cp "$build/Lamella.Grasshopper.gha" "$build/Lamella.dll" csharp/Lamella.Grasshopper/manifest.yml "$yak/bin/$framework/"
    cp "$build/liblamella_native.so" "$yak/bin/$framework/lamella_native.dll"
done
csharp/package-yak.sh win "$yak/bin" "$yak/dist" >/dev/null
for file in rh7-win/manifest.yml rh7-win/icon.png rh7-win/Lamella.Grasshopper.gha rh7-win/Lamella.dll rh7-win/lamella_native.dll \
    rh8-win/manifest.yml rh8-win/icon.png rh8-win/net48/Lamella.Grasshopper.gha rh8-win/net7.0/Lamella.dll rh8-win/net7.0/lamella_native.dll; do
    [ -f "$yak/dist/$file" ] || { echo "package-yak.sh did not stage $file"; exit 1; }
done
[ -z "$(find "$yak/dist" -mindepth 3 -name manifest.yml)" ] || { echo "package-yak.sh left a manifest below a package's top"; exit 1; }
if csharp/package-yak.sh mac "$yak/bin" "$yak/dist-mac" >/dev/null 2>&1; then
    echo "package-yak.sh staged a macOS package without liblamella_native.dylib"
    exit 1
fi

echo "== C#: tests"
"${mcs[@]}" -pkg:nunit -r:"$build/Lamella.dll" -out:"$build/Lamella.Tests.dll" -recurse:'csharp/Lamella.Tests/*.cs'

rm -f "$build/TestResult.xml"
status=0
# The panic test makes the library print a panic message on stderr; that is expected.
(cd "$build" && RUST_BACKTRACE=0 LAMELLA_HEADER="$root/include/lamella.h" \
    nunit-console -nologo -labels -xml=TestResult.xml Lamella.Tests.dll) || status=$?
python3 - "$build/TestResult.xml" "$status" <<'PY'
import sys
import xml.etree.ElementTree as ET

path, status = sys.argv[1], int(sys.argv[2])
try:
    cases = list(ET.parse(path).getroot().iter("test-case"))
except (OSError, ET.ParseError) as error:
    print(f"no test results ({error})")
    print("0 passed, 1 failed")
    sys.exit(1)
ran = [c for c in cases if c.get("executed") == "True"]
passed = sum(1 for c in ran if c.get("success") == "True")
failed = len(ran) - passed + len(cases) - len(ran)  # a test that did not run counts as failed
for c in cases:
    if c.get("success") != "True":
        print("FAILED:", c.get("name"))
print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed or status or not cases else 0)
PY
