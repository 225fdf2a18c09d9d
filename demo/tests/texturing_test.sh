#!/usr/bin/env bash
# The demo's texturing modes (sss_settings.texturing, --texturing), headless at 640x360:
#   texturing_test.sh SSS_DEMO IMAGE_CHECK MATERIAL_CHECK OUT_DIR ATTRIBUTION
# A bad value is refused with a message naming the option and the value; the close-up in each mode
# (the usual image checks, the settings text naming the mode, the zoom of the three side by side);
# post-scatter keeps more of the albedo's detail than pre-and-post, and that more than pre-scatter
# (material_check detail); the same with --msaa 4, where the lighting pass's multisampled albedo goes
# to the library's MSAA path (before it, an MSAA frame ran pre-scatter whatever the mode).
set -euo pipefail
demo=$1 image_check=$2 material_check=$3 out=$4 attribution=$5
rm -rf "$out"
mkdir -p "$out"
if "$demo" --headless --texturing sideways --out "$out/refused" 2>"$out/refused.txt"; then
  echo "FAIL: --texturing sideways was accepted" >&2
  exit 1
fi
grep -q "^sss_demo: --texturing wants pre, post or pre-and-post, got 'sideways'$" "$out/refused.txt" ||
  { echo "FAIL: no clear message for --texturing sideways:" >&2; cat "$out/refused.txt" >&2; exit 1; }
test ! -e "$out/refused" || { echo "FAIL: a refused run wrote $out/refused" >&2; exit 1; }
declare -A words=([pre]="pre-scatter (the colour blurred" [post]="post-scatter (the light alone blurred"
                  [pre-and-post]="pre-and-post-scatter (sqrt(albedo) blurred")
for mode in pre post pre-and-post; do
  "$demo" --headless --size 640x360 --preset close --repeat 1 --heat-factor 8 --dump --texturing "$mode" \
    --out "$out/$mode"
  "$image_check" headless "$out/$mode" "$attribution" close
  grep -qF "texturing ${words[$mode]}" "$out/$mode/README.txt" ||
    { echo "FAIL: README.txt's settings do not name texturing $mode" >&2; exit 1; }
  test -f "$out/$mode/close-zoom-texturing.png" || { echo "FAIL: no close-zoom-texturing.png" >&2; exit 1; }
done
# The default is post-scatter (docs/demo.md "Texturing modes" says why).
# (--help into a file first: with pipefail, grep -q closing the pipe early fails the demo's write.)
"$demo" --help > "$out/help.txt"
grep -q "post (the light alone blurred, the albedo's detail kept sharp; the default" "$out/help.txt" ||
  { echo "FAIL: --help does not name post-scatter the default" >&2; exit 1; }
"$material_check" detail "$out/pre" "$out/post" "$out/pre-and-post" close
for mode in pre post pre-and-post; do
  "$demo" --headless --size 640x360 --preset close --repeat 1 --heat-factor 8 --dump --texturing "$mode" --msaa 4 \
    --out "$out/msaa-$mode"
  "$image_check" headless "$out/msaa-$mode" "$attribution" close
  grep -qF "texturing ${words[$mode]}" "$out/msaa-$mode/README.txt" ||
    { echo "FAIL: with --msaa 4, README.txt's settings do not name texturing $mode" >&2; exit 1; }
done
"$material_check" detail "$out/msaa-pre" "$out/msaa-post" "$out/msaa-pre-and-post" close
