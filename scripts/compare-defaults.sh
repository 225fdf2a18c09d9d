#!/usr/bin/env bash
# The old and the new default side by side (docs/default-old-new.md and its pictures in docs/demo):
# builds the demo of an older revision (default: 4cb68e3, the last 0.1 default: Table 1 at
# width = 1.5 · world units per mm, fixed bilinear taps) in build/compare-old, renders the head's
# close-up and far shot with it and with this checkout's demo (960x540, EGL), and writes
#   docs/demo/default-old-new-close.png    the nose shadow, old | new, 3x
#   docs/demo/default-old-new-close-heat.png  the same crop of |result − exact| (heat scale 0.05)
#   docs/demo/default-old-new-far.png      the far head, old | new, 6x
#   docs/demo/default-old-new-far-heat.png
#   docs/default-old-new.md                the demo's interior miss, old and new, and the footprint
#                                          sweep's interior miss of the default (17 taps) from the
#                                          quick benchmark's miss baselines of both revisions
#
#   scripts/compare-defaults.sh [OLD_REVISION]
set -euo pipefail
cd "$(dirname "$0")/.."
old=${1:-4cb68e3}

scripts/install-deps.sh test demo
cmake -S . -B build/release -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build/release --parallel "$(nproc)" --target sss_demo sss_side_by_side
if [[ ! -d build/compare-old/src ]]; then
  git worktree add --force --detach build/compare-old/src "$old"
fi
git -C build/compare-old/src checkout --quiet --detach "$old"
# Commits before the head scan shipped in assets/ found it in ../shared/assets, beside their tree.
ln -sfn "$(cd .. && pwd)/shared" build/compare-old/shared
cmake -S build/compare-old/src -B build/compare-old/build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSS_BUILD_TESTS=OFF
cmake --build build/compare-old/build --parallel "$(nproc)" --target sss_demo

demo_new=$(find build/release -name sss_demo -type f | head -1)
demo_old=$(find build/compare-old/build -name sss_demo -type f | head -1)
for preset in close far; do
  (cd build/compare-old/src && "../../../$demo_old" --headless --backend egl --size 960x540 --heat-factor 2 \
     --preset "$preset" --out "../old-$preset")
  "$demo_new" --headless --backend egl --size 960x540 --heat-factor 2 --preset "$preset" --out "build/compare-old/new-$preset"
done
side=build/release/tools/sss_side_by_side
$side build/compare-old/old-close/close-after.png build/compare-old/new-close/close-after.png 430 250 160 140 3 docs/demo/default-old-new-close.png
$side build/compare-old/old-close/close-heatmap.png build/compare-old/new-close/close-heatmap.png 430 250 160 140 3 docs/demo/default-old-new-close-heat.png
$side build/compare-old/old-far/far-after.png build/compare-old/new-far/far-after.png 440 236 80 64 6 docs/demo/default-old-new-far.png
$side build/compare-old/old-far/far-heatmap.png build/compare-old/new-far/far-heatmap.png 440 236 80 64 6 docs/demo/default-old-new-far-heat.png

git show "$old:tests/bench/miss_baseline.csv" > build/compare-old/miss-old.csv
python3 scripts/compare_defaults_table.py --old-revision "$old" --old-miss build/compare-old/miss-old.csv \
  --new-miss tests/bench/miss_baseline.csv \
  --old-demo build/compare-old/old-close/README.txt build/compare-old/old-far/README.txt \
  --new-demo build/compare-old/new-close/README.txt build/compare-old/new-far/README.txt \
  --out docs/default-old-new.md
echo "wrote docs/default-old-new.md and docs/demo/default-old-new-*.png"
