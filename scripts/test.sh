#!/usr/bin/env bash
# Runs every test of the project:
#   1. the Rust suite: unit tests, integration tests under tests/, doc tests, and the check that
#      include/lamella.h matches what cbindgen generates from the source;
#   2. the C ABI from the outside (scripts/test-c-abi.sh): strict C99 harness under valgrind,
#      the header as C++17, the C and C++ examples;
#   3. view.html, the 3D viewer, rendered in headless Chromium (scripts/test-viewer.sh);
#   4. the C# binding and Grasshopper plugin under Mono (scripts/test-csharp.sh).
# Needs the Rust toolchain, cc/c++, valgrind, Chromium and Mono (the last three installed by their
# scripts if missing).
set -euo pipefail
cd "$(dirname "$0")/.."

# Each step prints how long it took, so that the whole run can be kept within its time budget.
step() {
    local started=$SECONDS
    "$@"
    echo "== $* took $((SECONDS - started)) s"
}

echo "== Rust tests"
step cargo test --locked

step scripts/test-c-abi.sh
step scripts/test-viewer.sh
step scripts/test-csharp.sh
echo "== all tests passed in $SECONDS s"
