#!/usr/bin/env bash
# Runs every test of the project:
#   1. the Rust suite: unit tests, integration tests under tests/, doc tests, and the check that
#      include/lamella.h matches what cbindgen generates from the source;
#   2. the C ABI from the outside (scripts/test-c-abi.sh): strict C99 harness under valgrind,
#      the header as C++17, the C and C++ examples;
#   3. the C# binding and Grasshopper plugin under Mono (scripts/test-csharp.sh).
# Needs the Rust toolchain, cc/c++, valgrind and Mono (the last two installed by their scripts if missing).
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== Rust tests"
cargo test --locked

scripts/test-c-abi.sh
scripts/test-csharp.sh
