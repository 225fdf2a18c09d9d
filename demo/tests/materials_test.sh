#!/usr/bin/env bash
# The demo's several-materials tests (issue 23), headless at 640x360.
#   materials_test.sh mixed SSS_DEMO IMAGE_CHECK MATERIAL_CHECK OUT_DIR ATTRIBUTION
#       the head, the marble bust and the wax candle (mid shot): the usual image checks, the profile
#       view's 4 colours (three profile/object pairs and the background), every object filtered.
#   materials_test.sh bleeding SSS_DEMO IMAGE_CHECK MATERIAL_CHECK OUT_DIR ATTRIBUTION
#       the hand in front of the face (close-up), object IDs on and off, the hand in two colours:
#       no light from the hand on the face with IDs (fp16), some without; the profile view's 3
#       colours with IDs (background, head, hand) and 2 without.
set -euo pipefail
what=$1 demo=$2 image_check=$3 material_check=$4 out=$5 attribution=$6
rm -rf "$out"
run() {  # run DIR PRESET [sss_demo arguments...]
  local dir=$1 preset=$2
  shift 2
  "$demo" --headless --size 640x360 --preset "$preset" --repeat 1 --heat-factor 8 --dump --out "$dir" "$@"
}
case $what in
  mixed)
    run "$out" mid --scene mixed
    "$image_check" headless "$out" "$attribution" mid
    "$material_check" colours "$out/mid-profiles.png" 4
    "$material_check" objects "$out" mid 3
    ;;
  bleeding)
    other=0.2,0.6,0.9  # a blue hand: far from skin in every channel
    # The hand's colour traces its light into the face: pre-scatter, where the albedo is blurred with
    # the light (post-scatter divides the hand's colour out before the blur, so no colour would cross).
    run "$out/ids-on" close --scene hand --texturing pre
    run "$out/ids-on-blue" close --scene hand --hand-colour "$other" --texturing pre
    run "$out/ids-off" close --scene hand --no-object-ids --texturing pre
    run "$out/ids-off-blue" close --scene hand --no-object-ids --hand-colour "$other" --texturing pre
    "$image_check" headless "$out/ids-on" "$attribution" close
    "$material_check" colours "$out/ids-on/close-profiles.png" 3
    "$material_check" colours "$out/ids-off/close-profiles.png" 2
    # The head is profile 0 object 1 (byte 16), the hand profile 0 object 2 (byte 32).
    "$material_check" bleed "$out/ids-on" "$out/ids-on-blue" "$out/ids-off" "$out/ids-off-blue" close 16 32
    ;;
  *) echo "materials_test.sh: unknown test $what" >&2; exit 2 ;;
esac
