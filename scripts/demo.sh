#!/usr/bin/env bash
# The main job: build, generate a million uniform points, triangulate them, check the result
# exactly, print the statistics.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh build
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DRIDT_BUILD_TESTS=OFF -DRIDT_BUILD_BENCH=OFF >/dev/null
cmake --build build --target ridt_tool
mkdir -p build/demo
build/ridt generate --dist uniform -n 1000000 --seed 1 -o build/demo/uniform.bin
build/ridt triangulate build/demo/uniform.bin -o build/demo/uniform.ele --stats=table --profile
build/ridt check build/demo/uniform.bin build/demo/uniform.ele
