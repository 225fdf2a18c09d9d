#!/usr/bin/env bash
# Regenerates the simulated profile data and what is derived from it, in one command:
#   data/profiles/<material>.csv   Monte Carlo R_d(r) per channel (tools/mc) beside the dipole
#   data/profiles/summary.csv      total diffuse reflectance, Monte Carlo and dipole
#   docs/profiles/<material>.png   dipole against Monte Carlo per material (gnuplot)
#   docs/kernel-fits.md            the kernel fits and decompositions (tools/kernel_report.cpp)
#   docs/burley.md's table         Burley's parameters of the materials (tools/burley_table.cpp)
#
#   scripts/generate-profiles.sh [--photons N] [--threads T] [--plots-only]
#
# Default 100000 photons per channel (1% of the supplementary's 10^7): about 2 CPU-minutes for all
# 33 channels, a few minutes on two shared cores; docs/profiles.md says why that is enough.
# --plots-only redraws the PNGs and the report from the committed CSVs.
set -euo pipefail
cd "$(dirname "$0")/.."

photons=100000
threads=$(nproc)
plots_only=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --photons) photons=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --plots-only) plots_only=1; shift ;;
    -h | --help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "generate-profiles.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done

scripts/install-deps.sh test  # gnuplot for the plots, nlohmann-json for the report
if [[ ! -f build/CMakeCache.txt ]]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSS_BUILD_DEMO=OFF
fi
cmake --build build --target sss_mc_profiles sss_kernel_report sss_burley_table

mkdir -p data/profiles docs/profiles
if [[ $plots_only == 0 ]]; then
  build/tools/sss_mc_profiles --out data/profiles --photons "$photons" --threads "$threads"
fi

for csv in data/profiles/*.csv; do
  name=$(basename "$csv" .csv)
  [[ $name == summary ]] && continue
  gnuplot <<GP
set terminal pngcairo size 900,560 font "sans,10"
set output "docs/profiles/${name}.png"
set datafile separator ","
set title "${name}: diffuse reflectance R_d(r), Monte Carlo (points) against the dipole (lines)"
set xlabel "r (mm)"
set ylabel "R_d(r) (mm^{-2})"
set logscale y
set format y "10^{%L}"
set key top right
stats "$csv" using 1 nooutput
set xrange [0:STATS_max]
# Nine decades below the peak: the Monte Carlo's last photons are around there.
stats "$csv" using (\$2 > \$4 ? \$2 : \$4) nooutput
set yrange [STATS_max * 1e-9 : STATS_max * 3]
plot "$csv" using 1:(\$2 > 0 ? \$2 : 1/0) every 4 with points pt 7 ps 0.3 lc rgb "#d62728" title "MC red", \
     "" using 1:(\$3 > 0 ? \$3 : 1/0) every 4 with points pt 7 ps 0.3 lc rgb "#2ca02c" title "MC green", \
     "" using 1:(\$4 > 0 ? \$4 : 1/0) every 4 with points pt 7 ps 0.3 lc rgb "#1f77b4" title "MC blue", \
     "" using 1:5 with lines lw 2 lc rgb "#8c1a1b" title "dipole red", \
     "" using 1:6 with lines lw 2 lc rgb "#1b6b1b" title "dipole green", \
     "" using 1:7 with lines lw 2 lc rgb "#174a73" title "dipole blue"
GP
done

build/tools/sss_kernel_report --out docs/kernel-fits.md
build/tools/sss_burley_table --update docs/burley.md
echo "generate-profiles: data/profiles/, docs/profiles/*.png, docs/kernel-fits.md and docs/burley.md's table written"
