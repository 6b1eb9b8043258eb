#!/usr/bin/env bash
# Runs every test of the project. Today that is the Rust suite: unit tests, integration
# tests under tests/ and doc tests. Needs only the Rust toolchain.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== Rust tests"
cargo test --locked
