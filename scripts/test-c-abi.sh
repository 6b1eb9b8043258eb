#!/usr/bin/env bash
# Checks Lamella's C ABI from the outside: builds the library, compiles the C harness
# (tests/c) as strict C99 and the header as C++17, runs the harness under valgrind (zero
# errors, zero leaks; its two parts side by side), and builds and runs the C and C++ examples
# (examples/c, examples/cpp), which must write the same curves and strips.
# Needs cargo, cc, c++ and valgrind (installed with apt-get if missing).
set -euo pipefail
cd "$(dirname "$0")/.."

target="${CARGO_TARGET_DIR:-target}"
lib="$target/debug"
build="$target/c-abi"
mkdir -p "$build"

echo "== C ABI: library"
# With --tests: the build `cargo test` made (dev-dependencies unify the dependencies' features;
# a plain `cargo build --lib` would rebuild every dependency for the other feature set).
cargo build --locked --lib --tests

if ! command -v valgrind >/dev/null; then
    echo "== C ABI: installing valgrind"
    apt-get update -qq && apt-get install -y -qq valgrind >/dev/null
fi

cflags=(-std=c99 -Wall -Wextra -Werror -pedantic -O1 -g -Iinclude)
cxxflags=(-std=c++17 -Wall -Wextra -Werror -O1 -g -Iinclude)
link=(-L"$lib" -Wl,-rpath,"$PWD/$lib" -llamella -lm -pthread)

echo "== C ABI: header as C99 and C++17"
echo '#include "lamella.h"' | cc "${cflags[@]}" -x c -fsyntax-only -
echo '#include "lamella.h"' | c++ "${cxxflags[@]}" -x c++ -fsyntax-only -

echo "== C ABI: harness"
cc "${cflags[@]}" tests/c/*.c "${link[@]}" -o "$build/harness"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
# Valgrind runs a process on one core, so the harness runs as its two parts side by side, each in
# its own scratch directory; the statuses each part provoked are then checked together.
# The suppression file covers only rayon's global worker threads, alive at exit (see the file).
run_part() {
    mkdir -p "$scratch/$1"
    RUST_BACKTRACE=0 valgrind --quiet --leak-check=full --errors-for-leak-kinds=definite,possible --num-callers=40 \
        --suppressions=tests/c/valgrind.supp --error-exitcode=1 "$build/harness" "$scratch/$1" "$1" \
        >"$scratch/$1.log" 2>&1
}
run_part starts & starts=$!
run_part pipeline & pipeline=$!
failed=0
wait "$starts" || failed=1
wait "$pipeline" || failed=1
for part in starts pipeline; do
    echo "-- harness part: $part"
    cat "$scratch/$part.log"
done
"$build/harness" --every-status-seen "$scratch/starts/statuses" "$scratch/pipeline/statuses" || failed=1
[ "$failed" = 0 ] || { echo "the C harness failed (see above)"; exit 1; }

echo "== C ABI: examples"
cc "${cflags[@]}" -Iexamples/c examples/c/*.c "${link[@]}" -o "$build/design_c"
cc "${cflags[@]}" -c examples/c/vault.c -o "$build/vault.o"
c++ "${cxxflags[@]}" -Iexamples/c -Iexamples/cpp examples/cpp/*.cpp "$build/vault.o" "${link[@]}" -o "$build/design_cpp"
mkdir -p "$scratch/c" "$scratch/cpp"
"$build/design_c" "$scratch/c"
# The C++ example reads the mesh the C example wrote, covering the OBJ path as well.
"$build/design_cpp" "$scratch/cpp" "$scratch/c/mesh.obj"
# Same mesh (through OBJ), same results: the C++ side even goes through a saved and restored session.
cmp <(cut -d, -f4 "$scratch/c/field.csv") <(cut -d, -f4 "$scratch/cpp/field.csv") >/dev/null \
    || { echo "the C and C++ examples disagree on the field"; exit 1; }
for obj in curves.obj strips.obj; do
    grep -q '^[lf] ' "$scratch/c/$obj" || { echo "$obj has no polylines or faces"; exit 1; }
    cmp "$scratch/c/$obj" "$scratch/cpp/$obj" >/dev/null || { echo "the C and C++ examples disagree on $obj"; exit 1; }
done
echo "== C ABI: all checks passed"
