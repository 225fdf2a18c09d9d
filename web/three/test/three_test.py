#!/usr/bin/env python3
"""The three.js package in a real browser (docs/three.md): serves a folder the packed package was
installed into (with three, lil-gui, the head scan at /head.glb and test/checks.js), opens the
package's example page in headless Chromium (SwiftShader's WebGL2) and checks

  1. the pass changes skin pixels, both spheres (marble; Burley's whole milk) and no background pixel;
  2. with the pass disabled the frame is bit-identical to three's own, rendered before the library
     existed; so is a frame of three's standard materials rendered after the pass;
  3. around each of the library's calls: no GL error, no difference in a snapshot of the GL state
     (bindings of every texture unit, buffers, framebuffers, program, vertex array, enables, blend,
     depth, stencil, masks, viewport, scissor, pixel store, the pass's textures' parameters), and
     three's state cache agrees with the GL (setting each cached value to what the GL holds makes
     three issue no GL call; a state changed behind three's back does);
  4. a setting the library refuses (1001 taps, a scale of NaN) puts its message on the page and leaves
     three's frame bit for bit; valid settings again give the filtered frame again;
  5. a new canvas size: the first frame after it compiles no shader and filters;
  6. split lighting: a glossy skin sphere under a point light: the composed output minus the blurred
     diffuse is three's specular within half-float rounding (and is not with the split off); with the
     split off, the pass off or strength 0 the frame is three's own bit for bit, a standard material
     without userData.sss is untouched, the albedo is the material's, the programs compile once;
  7. against the native frame (--native-apply): a frame of one profile (the head's skin), then the
     example's own frame of three profiles (skin, marble, Burley's whole milk), each with its inputs
     as the pass gave them to the library (colour, depth, profile texture, projection, every profile's
     floats and settings) filtered again natively on OpenGL ES 3.0 by sss_three_native_apply (which
     builds the kernels by the WebAssembly's own code); the pass's output against that: the miss
     (overall, per channel, per profile), and the tone-mapped frames within web.browser's limits.

  three_test.py --site DIR [--native-apply EXE] [--chromium PATH] [--out DIR] [--screenshot PNG] [--frames N]

Writes results.json (with the frame times, which no check reads) and the images into --out. Exit 0 on
success, 1 on a failed check, 77 when Chromium or the installed site is missing (ctest: a skip).
"""

import argparse
import array
import base64
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "test"))
import browser_test  # noqa: E402
import cdp  # noqa: E402
import images  # noqa: E402

WIDTH, HEIGHT = 640, 360
EXAMPLE = "node_modules/sss-three/example/index.html"


class Failure(Exception):
    pass


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        raise Failure(what)


def rgb(b64):
    return images.rgba_to_rgb(base64.b64decode(b64))


def changed(a, b, pixels):
    return sum(1 for i in pixels if a[i * 3:i * 3 + 3] != b[i * 3:i * 3 + 3])


def disk(centre, radius):
    cx, cy = centre
    return [y * WIDTH + x for y in range(max(0, cy - radius), min(HEIGHT, cy + radius + 1))
            for x in range(max(0, cx - radius), min(WIDTH, cx + radius + 1)) if (x - cx) ** 2 + (y - cy) ** 2 <= radius ** 2]


def run(browser, args, out_dir, results):
    js = browser.evaluate
    before = js("checks.before()")
    check(before["errors"] == [], "three alone: no GL error (%s)" % before["errors"])
    js("sssExample.proceed(); true")
    browser.wait_for("sssExample.ready || sssExample.failed", timeout=args.timeout)
    failed = js("sssExample.failed")
    check(failed is None, "the library runs on three's context (%s)" % failed)
    results["renderer"] = js("document.getElementById('renderer').textContent")
    print("     " + results["renderer"])

    three_only = rgb(before["composer"])
    lib = js("checks.withLibrary()")
    on, off = rgb(lib["on"]), rgb(lib["off"])
    check(lib["onResult"] == 0, "the pass filtered the frame (%s %s)" % (lib["onResult"], lib["onError"]))
    check(lib["errorsOn"] == [] and lib["errorsAfter"] == [], "no GL error after the frames (%s %s)" % (lib["errorsOn"], lib["errorsAfter"]))

    images.write_png(os.path.join(out_dir, "three-on.png"), WIDTH, HEIGHT, on)
    images.write_png(os.path.join(out_dir, "three-off.png"), WIDTH, HEIGHT, three_only)
    images.write_png(os.path.join(out_dir, "three-diff-x8.png"), WIDTH, HEIGHT,
                     images.difference_image(images.pixel_differences(on, three_only), 8))

    # 1. What the pass changes.
    n = WIDTH * HEIGHT
    background = three_only[0:3]
    scene_pixels = [i for i in range(n) if three_only[i * 3:i * 3 + 3] != background]
    background_pixels = [i for i in range(n) if three_only[i * 3:i * 3 + 3] == background]
    positions = js("checks.positions()")
    head = [i for i in disk(positions["head"], 60) if three_only[i * 3:i * 3 + 3] != background]
    results["changed"] = {"scene": changed(on, three_only, scene_pixels) / max(1, len(scene_pixels)),
                          "head_centre": changed(on, three_only, head) / max(1, len(head)),
                          "background": changed(on, three_only, background_pixels)}
    check(len(scene_pixels) > 0.2 * n, "the scene covers %.2f of the frame (> 0.2)" % (len(scene_pixels) / n))
    check(results["changed"]["head_centre"] > 0.3,
          "the pass changed %.2f of the face's pixels (> 0.3)" % results["changed"]["head_centre"])
    check(results["changed"]["background"] == 0, "the pass changed %d background pixels (0)" % results["changed"]["background"])
    for name in ("marble", "milk"):
        sphere = disk(positions[name], 12)
        share = changed(on, three_only, sphere) / len(sphere)
        results["changed"][name] = share
        check(share > 0.1, "the pass changed %.2f of the %s sphere's centre (> 0.1)" % (share, name))

    # 2. No leak into three's frames.
    check(off == three_only, "the pass disabled: the frame is three's own, bit for bit")
    check(rgb(lib["standard"]) == rgb(before["standard"]),
          "three's standard materials after the pass: the frame as without the library, bit for bit")

    # The composer's frame splits too: over the glossy skin sphere, the split frame differs from three's
    # by the diffuse light's blur alone; blurring the whole lit colour (splitLighting false) adds the
    # highlight's blur to it (the sum of |8-bit level differences| over the sphere's disk).
    unsplit = rgb(js("checks.unsplitFrame()"))
    glossy = disk(positions["glossy"], 25)
    off_by = lambda image: sum(abs(a - b) for i in glossy for a, b in zip(image[i * 3:i * 3 + 3], three_only[i * 3:i * 3 + 3]))
    results["glossy_sphere_levels_off"] = {"split": off_by(on), "unsplit": off_by(unsplit)}
    check(off_by(unsplit) > 2 * off_by(on),
          "the glossy sphere: the split frame %d levels from three's over its disk, the whole colour blurred %d (> 2x)"
          % (off_by(on), off_by(unsplit)))

    # 3. Around each of the library's calls.
    results["cache_calls_before_the_library"] = lib["around"][0]["syncCalls"] if lib["around"] else None
    check(len(lib["around"]) == 1, "one library call per frame (%d)" % len(lib["around"]))
    for call in lib["around"]:
        check(call["result"] == 0, "the library's call succeeded (%s)" % call["result"])
        check(call["errors"] == [], "no GL error after the library's call (%s)" % call["errors"])
        check(call["differences"] == [], "no GL state difference around the library's call (%s)" % call["differences"][:8])
        check(call["cacheCalls"] == [], "three's state cache agrees with the GL after the call (calls: %s)" % call["cacheCalls"])
    check(len(lib["staleProbeCalls"]) > 0, "the probe sees a stale cache: DEPTH_TEST flipped behind three's back cost %s"
          % lib["staleProbeCalls"])
    results["stats"] = lib["stats"]

    # 4. Settings the library refuses.
    for name, value, words in (("taps", 1001, ["taps", "1001"]), ("scale", float("nan"), ["scale", "nan"])):
        bad = js("checks.badSetting(%s, %s)" % (json.dumps(name), "NaN" if value != value else json.dumps(value)))
        results["refused_" + name] = bad["message"]
        check(bad["result"] != 0 and bad["message"].startswith("SSS_ERROR_INVALID_ARGUMENT")
              and all(w in bad["message"].lower() for w in words), "%s %s: the library's message: %r" % (name, value, bad["message"]))
        check(bad["shown"] == bad["message"], "%s %s: the page shows it" % (name, value))
        check(rgb(bad["image"]) == three_only, "%s %s: three's frame, bit for bit" % (name, value))
        check(bad["errors"] == [], "%s %s: no GL error" % (name, value))
        check(bad["validResult"] == 0 and bad["validMessage"] == "" and rgb(bad["validAgain"]) == on,
              "%s valid again: filtered as before, the message cleared" % name)

    # 5. A new size.
    resized = js("checks.resize(800, 450)")
    results["resize"] = resized
    check(resized["result"] == 0 and resized["frames"] == 1 and resized["size"] == [800, 450],
          "800x450: the first frame filtered (%s)" % resized["message"])
    check(resized["compiles"] == 0, "800x450: no shader compiled in the frame after setSize (%d)" % resized["compiles"])
    check(resized["errors"] == [] and resized["backResult"] == 0, "800x450 and back: no GL error, filtered")

    # 6. Split lighting.
    split_lighting(js, out_dir, results)
    split_features(js, results)
    texturing(js, results)

    # Pictures and times (read by people, never judged).
    times = js("sssExample.time(%d)" % args.frames)
    results["frame_ms"] = {"with_pass": round(times["on"], 1), "with_pass_unsplit": round(times["unsplit"], 1),
                           "without_pass": round(times["off"], 1), "frames": args.frames}
    print("     frame %.1f ms with the pass, %.1f ms with it and splitLighting off, %.1f ms without (median of %d)"
          % (times["on"], times["unsplit"], times["off"], args.frames))
    js("sssExample.pass.enabled = false; true")
    unsplit = rgb(js("checks.split(0.5)"))  # the example's own background from here on
    unsplit_full = rgb(js("checks.split(0)"))
    js("sssExample.pass.enabled = true; true")
    split = rgb(js("checks.split(0.5)"))
    images.write_png(os.path.join(out_dir, "three-split.png"), WIDTH, HEIGHT, split)
    left = [y * WIDTH + x for y in range(HEIGHT) for x in range(WIDTH // 2 - 1)]
    right = [y * WIDTH + x for y in range(HEIGHT) for x in range(WIDTH // 2 + 1, WIDTH)]
    check(changed(split, unsplit, left) == 0 and changed(split, unsplit, right) > 0,
          "split view: the left half is three's own frame, the right half filtered")
    if args.screenshot:
        with open(args.screenshot, "wb") as f:
            f.write(browser.screenshot_png(1000, 720))
    js("checks.split(0)")

    # What the calls that draw nothing leave bound: nothing, with three's objects lent their names.
    setup = js("checks.setupCalls()")
    results["state_after_setup_calls"] = setup
    for name in ("sss_create", "sss_prepare", "sss_destroy"):
        print("     %s leaves %d differences: %s" % (name, len(setup[name]), setup[name][:6]))
    check(setup["errors"] == [], "create, prepare, destroy of a second context: no GL error")
    check(setup["sss_create"] == [] and setup["sss_prepare"] == [] and setup["sss_destroy"] == [],
          "sss_create, sss_prepare and sss_destroy leave the GL state as they found it")
    js("sssExample.pass.enabled = false; true")
    check(rgb(js("checks.split(0)")) == unsplit_full, "after them: three's frame as before, bit for bit")
    js("sssExample.pass.enabled = true; true")

    # Why the package lends names: without them the library restores three's bindings to nothing.
    unlent = js("checks.withoutLending()")
    results["state_without_lending"] = unlent
    check(len(unlent) > 0, "without lent names the library's restore differs in %d places (%s)" % (len(unlent), unlent[:6]))

    # 7. Against the native frame.
    if args.native_apply:
        against_native(js, args.native_apply, out_dir, results)
    else:
        print("skip against the native frame: no --native-apply (ctest passes sss_three_native_apply)")


# The miss's bound. Both sides run the library's shaders on the same inputs; what may differ is the
# rasteriser's float32 arithmetic (SwiftShader against llvmpipe: fused multiply-adds, exp2 and
# division, the order of sums) and so where a value lands among the half floats the library's passes
# write (the intermediate blurred target and the output): one half-float step, 2^-10 of the value.
# The change the pass makes is small beside the skin's colour, so half a step on every filtered value
# would already leave fp16_explained (results.json: FP16_HALF_STEP * sum |native| / sum of the change)
# of the change undone: 0.08 measured. Measured miss: 0, the two outputs bit for bit equal (both
# rasterisers round these shaders' float32 results into the same half floats). The bound lets one
# filtered value in eight land one step away (1/8 * 2 * 0.08 = 0.02), what another SwiftShader or
# Mesa with other rounding may do, and no more: a scattering distance 5 % off (scale 1.05 natively)
# measured a miss of 0.061, the depth taken as [0, 1] clip depth (flags 1) 1.25. The example's frame
# of three profiles: one float of 330560 a half-float step away (marble, green), miss 1e-6 overall
# (marble 4e-6); half a step everywhere would leave 0.086 undone (skin 0.081, marble 0.068, whole
# milk 0.147); every scale 5 % off: 0.070 (skin 0.061, marble 0.091, whole milk 0.076). Each profile
# is held to the same bound.
MISS_BOUND = 0.02
FP16_HALF_STEP = 2.0 ** -11
# The floats of one profile the pass hands sss3_set_profiles (wasm/profile_fields.hpp), and where
# among them its texturing is (kTexturing: 0 pre-scatter, 1 post-scatter, 2 both).
PROFILE_FLOATS = 17
TEXTURING_FIELD = 16
# Post-scatter (the example's skin): each side divides the colour by the albedo and multiplies the
# blur by it again, in float32, reading the SRGB8_ALPHA8 albedo through its own GPU's sRGB decode
# (SwiftShader's and llvmpipe's differ in the last bits), so an output may round to the half float
# next to the other side's where pre-scatter's landed on the same one: measured on the head's skin,
# 21-27 % of the values one step away (per channel), 0.2 % two, a few dozen of 72614 pixels 3-5 (the
# quotient's difference carried through the blur). That step is forgiven on a post-scatter profile's
# pixels (miss_of's `forgiven`) and what is left is held to MISS_BOUND: measured 0.00015, where the
# miss with it unforgiven is 0.034 (the change post-scatter makes is smaller than pre-scatter's: the
# albedo's detail is not blurred, so one step weighs more). The check's own test still fails it:
# the scale 5 % off natively, one step forgiven, 0.029.
POST_SCATTER_FORGIVEN = 1


# The split's bound. Three's specular S (the skin material with a black diffuse colour: with metalness
# 0 nothing of three's specular depends on it) is a float32 value rounded once to half float; the
# split's way to it rounds twice more: the unblurred light U = round16(three's colour - diffuse) in
# the split's attachment, then the compose's blend C = round16(B + U) onto the blurred diffuse B
# (read back exactly: it is a half float). Each rounding is at most half a step, 2^-11 of the value
# rounded, so |C - B - S| <= 2^-11 (|C| + |U| + |S|), plus float32's own (three's colour minus its
# diffuse, and the black-diffuse program's specular against the split program's: 2^-24 of the
# colour, 2^-8 of the bound is far more) and half a half float's smallest step for values that land
# among the subnormals (2^-25; 2^-23 covers three of them). Measured: every skin pixel within it
# (SPLIT_WORST_RATIO in results.json: the largest |C - B - S| over its bound). The check's own test:
# with splitLighting false the library blurs the specular with the diffuse (C - B = 0), and the
# highlight's pixels lie far outside the bound.
SPLIT_RELATIVE = FP16_HALF_STEP * (1 + 2.0 ** -8)
SPLIT_ABSOLUTE = 2.0 ** -23


def f32(b64):
    a = array.array("f")
    a.frombytes(base64.b64decode(b64))
    return a


def split_residuals(frame, specular, pixels):
    """Of PIXELS (RGB): C - B - S over its bound, and the pixels beyond the bound."""
    composed, blurred, unblurred = f32(frame["composed"]), f32(frame["blurred"]), f32(frame["unblurred"])
    worst, beyond = 0.0, 0
    for i in pixels:
        out = False
        for c in range(3):
            k = i * 4 + c
            residual = abs(composed[k] - blurred[k] - specular[k])
            bound = SPLIT_RELATIVE * (abs(composed[k]) + abs(unblurred[k]) + abs(specular[k])) + SPLIT_ABSOLUTE
            worst = max(worst, residual / bound)
            out = out or residual > bound
        beyond += out
    return worst, beyond


def split_features(js, results):
    # Clearcoat, sheen, transmission, emissive with a map, fog: what three adds after the diffuse sum
    # lands in the unblurred light, so composed - blurred = three's colour - the diffuse handed. The
    # same roundings as SPLIT_RELATIVE's, with three's colour F for S and the handed diffuse D (a half
    # float, exact) beside it: |C - B - (F - D)| <= 2^-11 (|C| + |U| + |F|) + float32's.
    got = js("checks.splitFeatures()")
    n = got["width"] * got["height"]
    on = got["on"]
    check(on["result"] == 0 and got["errors"] == [], "split features: filtered, no GL error (%s %s)" % (on["message"], got["errors"]))
    three, composed, blurred = f32(got["three"]), f32(on["composed"]), f32(on["blurred"])
    handed, unblurred = f32(on["handed"]), f32(on["unblurred"])
    profile = base64.b64decode(on["profile"])
    worst, beyond, counts = 0.0, 0, {}
    for i in range(n):
        p = profile[i] & 15
        if p == 15:
            continue
        counts[profile[i] >> 4] = counts.get(profile[i] >> 4, 0) + 1
        for c in range(3):
            k = i * 4 + c
            residual = abs(composed[k] - blurred[k] - (three[k] - handed[k]))
            bound = SPLIT_RELATIVE * (abs(composed[k]) + abs(unblurred[k]) + abs(three[k])) + SPLIT_ABSOLUTE
            worst = max(worst, residual / bound)
            beyond += residual > bound
    results["split_features"] = {"pixels_per_sphere": counts, "worst_ratio": worst, "beyond": beyond}
    print("     split features (clearcoat, sheen, transmission, emissive + map; fog): worst %.3f of the bound" % worst)
    check(len(counts) == 4 and min(counts.values()) > 500, "split features: four spheres drawn split (%s)" % counts)
    check(beyond == 0, "split features: composed - blurred = three's colour - the diffuse, within half-float rounding "
          "(worst %.3f of the bound)" % worst)


# The post-scatter bound (texturing). Under an ambient light alone the irradiance E is the same at
# every pixel, so the blur of the light alone is E again, and a post-scatter frame is three's own
# frame F = E A (+ its specular, here 0, through the split's unblurred attachment) but for roundings.
# The library divides the handed diffuse D = E A by the split's albedo A' (A re-encoded to sRGB 8
# bits: |A' / A - 1| <= q, half an 8-bit step relative, q = (decode(b + 1/2) - decode(b)) / decode(b)
# at the darkest level b of the frame's albedo, per channel), blurs the light L = D / A' = E A / A',
# each within [E (1 - q), E (1 + q)], with weights that sum to 1, and multiplies by A' again: the
# output lies within E A' (1 +- q) = E A (1 +- q)^2, 2q / (1 - q) relative (first order) of F. Half-
# float roundings on the way: F and D (three's target), L (the library's copy), the intermediate
# blurred target, the output, the compose: six half steps, 6 * 2^-11 of the value; and the absolute
# floor of SPLIT_ABSOLUTE for the unblurred light's subnormals. Measured: texturing_post_worst_ratio
# in results.json, the largest |C - F| over that bound (the map's texels re-encode to their own byte,
# A' = A: only the half floats' share shows). The check's own test: pre-scatter blurs the noise of
# albedos 0.35-1 of the skin's (texels of 2.8 pixels, the kernel a few pixels wide): most of the
# plane lies far outside the bound.
TEXTURING_FP16_STEPS = 6


def srgb_decode(level):
    v = level / 255.0
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def texturing(js, results):
    got = js("checks.texturing()")
    n = got["width"] * got["height"]
    three = f32(got["three"])
    frames = ("post", "pre", "preNamed", "prePost", "postAgain", "preUnsplit", "postUnsplit", "lambertPre", "lambertPost")
    check(all(got[k]["result"] == 0 for k in frames) and got["errors"] == [],
          "texturing: every frame filtered, no GL error (%s %s)" % ([got[k]["message"] for k in frames], got["errors"]))
    post = got["post"]
    profile = base64.b64decode(post["profile"])
    albedo = base64.b64decode(post["albedo"])
    plane = [i for i in range(n) if profile[i] & 15 != 15]
    check(len(plane) == n, "texturing: the skin plane covers the frame (%d of %d pixels)" % (len(plane), n))
    # Half an sRGB-8 step relative at the darkest albedo level of each channel.
    q = [max((srgb_decode(b + 0.5) - srgb_decode(b)) / srgb_decode(b) for b in {albedo[i * 4 + c] for i in plane})
         for c in range(3)]
    relative = [2 * qc / (1 - qc) + TEXTURING_FP16_STEPS * FP16_HALF_STEP for qc in q]

    def off(frame):
        composed = f32(frame["composed"])
        worst, beyond = 0.0, 0
        for i in plane:
            out = False
            for c in range(3):
                k = i * 4 + c
                bound = relative[c] * abs(three[k]) + SPLIT_ABSOLUTE
                worst = max(worst, abs(composed[k] - three[k]) / bound)
                out = out or abs(composed[k] - three[k]) > bound
            beyond += out
        return worst, beyond / len(plane)

    post_worst, post_beyond = off(post)
    again_worst, again_beyond = off(got["postAgain"])
    pre_worst, pre_beyond = off(got["pre"])
    both_worst, both_beyond = off(got["prePost"])
    same = lambda a, b: base64.b64decode(got[a]["composed"]) == base64.b64decode(got[b]["composed"])
    results["texturing"] = {"pixels": len(plane), "relative_bound": relative, "post_worst_ratio": post_worst,
                            "post_again_worst_ratio": again_worst, "pre_worst_ratio": pre_worst,
                            "pre_share_beyond": pre_beyond, "pre_and_post_worst_ratio": both_worst,
                            "pre_and_post_share_beyond": both_beyond, "unknown_message": got["unknown"]["message"]}
    print("     texturing, uniform light over a noise albedo: post-scatter at most %.3f of its bound (%.4f relative "
          "in red); pre-scatter %.1f (%.2f of the plane beyond), pre-and-post %.1f (%.2f beyond)"
          % (post_worst, relative[0], pre_worst, pre_beyond, both_worst, both_beyond))
    check(post["albedoFormat"] == 0x8C43 and got["postAgain"]["albedoFormat"] == 0x8C43,
          "texturing: post-scatter hands the library the split's albedo (SRGB8_ALPHA8)")
    check(post_beyond == 0 and again_beyond == 0,
          "texturing: post-scatter under uniform light is three's own frame within the sRGB-8 and half-float roundings "
          "(worst %.3f of the bound; again %.3f)" % (post_worst, again_worst))
    check(pre_beyond > 0.25, "texturing: the check's own test: pre-scatter blurs the albedo: %.2f of the plane beyond "
          "the bound (> 0.25), worst %.1f times it" % (pre_beyond, pre_worst))
    check(both_beyond > 0 and both_worst < pre_worst,
          "texturing: pre-and-post-scatter blurs less than pre-scatter (worst %.1f against %.1f)" % (both_worst, pre_worst))
    check(got["pre"]["albedoFormat"] == 0 and got["preNamed"]["albedoFormat"] == 0 and same("pre", "preNamed"),
          "texturing: 'pre' and no texturing: no albedo handed, the same frame bit for bit")
    check(same("preUnsplit", "postUnsplit") and got["postUnsplit"]["albedoFormat"] == 0,
          "texturing: splitLighting off: 'post' falls back to pre-scatter, bit for bit, no albedo handed")
    check(same("lambertPre", "lambertPost") and got["lambertPost"]["albedoFormat"] == 0,
          "texturing: a Lambert material (no split): 'post' falls back to pre-scatter, bit for bit, no albedo handed")
    unknown = got["unknown"]
    check(unknown["result"] != 0 and "texturing" in unknown["message"],
          "texturing: a name the pass does not know ('after'): the library's message: %r" % unknown["message"])


def split_lighting(js, out_dir, results):
    got = js("checks.splitLighting()")
    width, height = got["width"], got["height"]
    n = width * height
    three, specular = f32(got["three"]), f32(got["specular"])
    on = got["on"]
    check(all(got[k]["result"] == 0 for k in ("first", "on", "noSplit", "zero", "onAgain")),
          "split lighting: the pass filtered every frame (%s)" % got["on"]["message"])
    check(got["errors"] == [], "split lighting: no GL error (%s)" % got["errors"])
    profile = base64.b64decode(on["profile"])
    skin = [i for i in range(n) if profile[i] & 15 == 0]
    others = [i for i in range(n) if profile[i] & 15 == 15]
    plain = [i for i in others if any(three[i * 4 + c] != 0 for c in range(3))]
    highlight = max(specular[i * 4 + c] for i in skin for c in range(3)) if skin else 0
    check(len(skin) > 2000 and len(plain) > 2000, "split lighting: the skin sphere covers %d pixels, the plain one %d (> 2000)"
          % (len(skin), len(plain)))
    check(highlight > 0.1, "split lighting: three's specular on the skin sphere peaks at %.3f (> 0.1: a highlight)" % highlight)
    blurred, handed = f32(on["blurred"]), f32(on["handed"])
    filtered = sum(1 for i in skin if any(blurred[i * 4 + c] != handed[i * 4 + c] for c in range(3)))
    check(filtered > 0.5 * len(skin), "split lighting: the library changed %d of the skin's pixels" % filtered)
    worst, beyond = split_residuals(on, specular, skin)
    worst_again, beyond_again = split_residuals(got["onAgain"], specular, skin)
    off_worst, off_beyond = split_residuals(dict(got["noSplit"], unblurred=got["noSplit"]["composed"]), specular, skin)
    composed = f32(on["composed"])
    steps = max(abs(composed[i * 4 + c] - blurred[i * 4 + c] - specular[i * 4 + c]) /
                max(2.0 ** -24, 2.0 ** (math.floor(math.log2(max(abs(composed[i * 4 + c]), 2.0 ** -14))) - 10))
                for i in skin for c in range(3))
    results["split_lighting"] = {
        "skin_pixels": len(skin), "plain_pixels": len(plain), "specular_peak": highlight,
        "worst_ratio": worst, "worst_steps": steps, "beyond": beyond, "worst_ratio_again": worst_again,
        "no_split_worst_ratio": off_worst, "no_split_beyond": off_beyond,
        "first_frames": got["firstFrames"], "steady_frames": got["steadyFrames"], "programs": got["programs"]}
    print("     split: |composed - blurred - specular| at most %.3f of its bound (%.2f half-float steps of the output); "
          "split off: %.1f, %d pixels beyond" % (worst, steps, off_worst, off_beyond))
    check(beyond == 0 and beyond_again == 0,
          "split lighting: composed - blurred diffuse = three's specular within half-float rounding on every skin pixel "
          "(worst %.3f of the bound; again %.3f)" % (worst, worst_again))
    check(off_beyond > 0.05 * len(skin),
          "split lighting: the check's own test: with splitLighting false %d skin pixels lie beyond the bound (> 5 %%)" % off_beyond)
    exact = lambda frame: base64.b64decode(frame) == base64.b64decode(got["three"])
    check(exact(got["zero"]["composed"]), "split lighting: strength 0: three's frame, bit for bit")
    check(exact(got["off"]), "split lighting: the pass off (no call armed the frame): three's frame, bit for bit")
    check(all(composed[i * 4 + c] == three[i * 4 + c] for i in others for c in range(4)),
          "split lighting: the standard material without userData.sss and the background: three's colour, bit for bit")
    albedo = base64.b64decode(on["albedo"])
    unblurred_on = f32(on["unblurred"])
    check(all(albedo[i * 4 + c] == 0 and unblurred_on[i * 4 + c] == 0 for i in others for c in range(4)),
          "split lighting: the split's attachments hold 0 on the plain material and the background")
    expected = [srgb8(v) for v in got["skinColour"]]
    albedo_off = max(abs(albedo[i * 4 + c] - expected[c]) for i in skin for c in range(3))
    check(albedo_off <= 1, "split lighting: the albedo attachment holds the skin's colour, sRGB-encoded %s (within %d level)"
          % (expected, albedo_off))
    first, steady, programs = got["firstFrames"], got["steadyFrames"], got["programs"]
    print("     split: the first frames compiled %d shaders, linked %d programs; the nine scene renders after %d, %d"
          % (first["compiles"], first["links"], steady["compiles"], steady["links"]))
    check(steady["compiles"] == 0 and steady["links"] == 0,
          "split lighting: no shader compiled in the nine scene renders after, toggling the split, strength and the pass (%d compiles)" % steady["compiles"])
    fb = got["framebuffer"]
    check(fb["drawBuffers"] == [0x8CE0, 0, 0] and fb["attachments"] == [0, 0],
          "split lighting: the target's framebuffer after the split frames as three made it (draw buffers %s, "
          "attachments 1-2 %s)" % (fb["drawBuffers"], fb["attachments"]))
    check(programs["splitKey"] in programs["skin"] and programs["splitKey"] not in programs["plain"] and not programs["shared"],
          "split lighting: the patched material has a program of its own, the plain one three's")


def srgb8(x):
    # A plain sRGB encode of clamp(x) (exposure 1) to 8 bits: the frames compared the way
    # web.browser compares the page's, without three's ACES curve (the same on both sides).
    x = min(1.0, max(0.0, x))
    x = 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
    return int(round(x * 255))


def write_params(directory, params):
    with open(os.path.join(directory, "params.txt"), "w") as f:
        for name, values in params.items():
            f.write(name + " " + " ".join(repr(float(v)) for v in values) + "\n")


def native_run(native_apply, directory, params):
    """sss_three_native_apply on DIRECTORY's inputs with PARAMS: its JSON line, or None when it failed."""
    write_params(directory, params)
    run = subprocess.run([native_apply, directory], capture_output=True, text=True, timeout=300)
    print("     native: " + run.stdout.strip() + (" " + run.stderr.strip() if run.stderr.strip() else ""))
    return json.loads(run.stdout.strip().splitlines()[-1]) if run.returncode == 0 else None


def floats(directory, name):
    a = array.array("f")
    with open(os.path.join(directory, name), "rb") as f:
        a.frombytes(f.read())
    return a


def half_step(v):
    """One half-float step at v (2^-10 of its power of two; the subnormals' 2^-24 below 2^-14)."""
    return 2.0 ** (math.floor(math.log2(max(abs(v), 2.0 ** -14))) - 10)


def miss_of(web, native, colour, pixels, forgiven=frozenset()):
    """The share of the native change (native - colour) that web leaves undone: sums over PIXELS of
    |web - native| and |native - colour| (RGB; alpha is never filtered), per channel, and of |native|.
    At the pixels in FORGIVEN (post-scatter profiles': POST_SCATTER_FORGIVEN) one half-float step of
    |web - native| is forgiven."""
    off, change, scale = [0.0] * 3, [0.0] * 3, [0.0] * 3
    for i in pixels:
        for c in range(3):
            k = i * 4 + c
            d = abs(web[k] - native[k])
            off[c] += max(0.0, d - POST_SCATTER_FORGIVEN * half_step(native[k])) if i in forgiven else d
            change[c] += abs(native[k] - colour[k])
            scale[c] += abs(native[k])
    return (sum(off) / max(1e-30, sum(change)), [off[c] / max(1e-30, change[c]) for c in range(3)],
            FP16_HALF_STEP * sum(scale) / max(1e-30, sum(change)))


# The example's three profiles, by the kind the pass gave each (wasm/profile_fields.hpp's ProfileKind).
EXAMPLE_PROFILES = {0: "skin", 1: "marble", 2: "whole milk"}


def tone_mapped(web, native, pixels):
    """Of PIXELS: the share beyond web.browser's small and outlier limits (8-bit sRGB), the largest difference."""
    beyond_small = beyond_outlier = largest = 0
    for i in pixels:
        d = max(abs(srgb8(web[i * 4 + c]) - srgb8(native[i * 4 + c])) for c in range(3))
        largest = max(largest, d)
        beyond_small += d > browser_test.SMALL_LEVELS
        beyond_outlier += d > browser_test.OUTLIER_LEVELS
    return beyond_small / max(1, len(pixels)), beyond_outlier / max(1, len(pixels)), largest


def against_native(js, native_apply, out_dir, results):
    # The single profile (the head's skin, the spheres not translucent), then the example's own frame
    # of three profiles (skin; marble, measured; Burley's whole milk), split off in both.
    results["against_native"] = against_native_frame(js, native_apply, out_dir, True)
    results["against_native_three"] = against_native_frame(js, native_apply, out_dir, False)


def against_native_frame(js, native_apply, out_dir, single):
    what = "one profile" if single else "three profiles"
    got = js("checks.nativeInputs(%s)" % ("true" if single else "false"))
    check(got["result"] == 0 and got.get("frame") is not None and got.get("profiles") is not None,
          "%s: the pass filtered (%s %s)" % (what, got["result"], got["message"]))
    check(got["errors"] == [], "%s: no GL error, the inputs read back (%s)" % (what, got["errors"]))
    profiles, frame, settings = got["profiles"], got["frame"], got["settings"]
    fields, count = profiles["fields"], profiles["count"]
    kinds = [int(fields[i * PROFILE_FLOATS]) for i in range(count)]
    texturings = [int(fields[i * PROFILE_FLOATS + TEXTURING_FIELD]) for i in range(count)]
    defaults = {"metresPerUnit": 1, "scale": 1, "strength": 1, "falloff": 1, "taps": 17, "followSurface": True,
                "path": "auto", "jitter": 0, "split": 0}
    expected = [0] if single else [0, 1, 2]
    check(sorted(kinds) == expected and all(settings[k] == v for k, v in defaults.items() if k != "split"),
          "%s: %s, the default settings (kinds %s, %s)" % (what, "the skin kernel" if single else
                                                           "skin, measured and Burley-measured kernels", kinds, settings))
    width, height = frame["width"], frame["height"]
    native_dir = os.path.join(out_dir, "native" if single else "native-three")
    os.makedirs(native_dir, exist_ok=True)
    # The example's skin (the head and the glossy sphere) is post-scatter: the pass handed the library
    # the split's albedo, which goes to the native side too (albedo.u8, its SRGB8_ALPHA8 bytes).
    skin_texturing = texturings[kinds.index(0)] if 0 in kinds else None
    check(skin_texturing == 1 and frame["albedoFormat"] == 0x8C43 and got.get("albedo") is not None,
          "%s: the skin post-scatter, with the split's albedo (SRGB8_ALPHA8) handed to the library (texturings %s, format 0x%x)"
          % (what, texturings, frame["albedoFormat"] or 0))
    for name in ("colour", "depth", "profile", "web", "albedo"):
        with open(os.path.join(native_dir, name + {"profile": ".u8", "albedo": ".u8"}.get(name, ".f32")), "wb") as f:
            f.write(base64.b64decode(got[name]))
    # What the pass gave sss3_set_profiles (all of its scratch floats) and sss3_apply.
    params = {"width": [width], "height": [height], "projection": frame["projection"], "count": [count],
              "fields": fields, "taps": [profiles["taps"]], "follow_surface": [profiles["followSurface"]],
              "path": [profiles["path"]], "jitter": [profiles["jitter"]], "noise_index": [frame["noiseIndex"]],
              "flags": [frame["flags"]], "albedo_format": [frame["albedoFormat"]]}
    native_info = native_run(native_apply, native_dir, params)
    check(native_info is not None, "%s: sss_three_native_apply filtered the same inputs on OpenGL ES 3.0" % what)
    colour, web, native = floats(native_dir, "colour.f32"), floats(native_dir, "web.f32"), floats(native_dir, "native.f32")
    profile = open(os.path.join(native_dir, "profile.u8"), "rb").read()
    n = width * height
    filtered = [i for i in range(n) if profile[i] & 15 < count]
    others = [i for i in range(n) if profile[i] & 15 >= count]
    per_profile = {EXAMPLE_PROFILES.get(kinds[j], "kind %d" % kinds[j]): [i for i in filtered if profile[i] & 15 == j]
                   for j in range(count)}
    check(len(filtered) > 0.05 * n, "%s: they cover %.3f of the frame (> 0.05)" % (what, len(filtered) / n))
    check(all(len(px) > 0 for px in per_profile.values()),
          "%s: every profile has pixels (%s)" % (what, {k: len(v) for k, v in per_profile.items()}))
    # Pixels without a profile: both sides leave them as three drew them.
    untouched = all(web[i * 4 + c] == colour[i * 4 + c] == native[i * 4 + c] for i in others for c in range(4))
    check(untouched, "%s: pixels without a profile: three's colour in both, bit for bit" % what)

    # (a) The miss with the native output as the reference: the share of the change it makes that
    # the pass's output does not make the same, per channel and overall (and per profile).
    post_scatter = [j for j in range(count) if texturings[j] != 0]
    forgiven = frozenset(i for i in filtered if profile[i] & 15 in post_scatter)
    miss, per_channel, fp16_explained = miss_of(web, native, colour, filtered, forgiven)
    unforgiven = miss_of(web, native, colour, filtered)[0]
    # (b) The tone-mapped frames (8 bits) within web.browser's limits, over the filtered pixels.
    small_share, outlier_share, largest = tone_mapped(web, native, filtered)
    out = {
        "native_renderer": native_info["renderer"], "skin_pixels" if single else "pixels": len(filtered), "miss": miss,
        "miss_per_channel": per_channel, "miss_bound": MISS_BOUND, "fp16_explained": fp16_explained,
        "share_beyond_small": small_share,
        "share_beyond_outlier": outlier_share, "largest_levels": largest,
        "small_levels": browser_test.SMALL_LEVELS, "small_share_limit": browser_test.SMALL_SHARE,
        "outlier_levels": browser_test.OUTLIER_LEVELS, "outlier_share_limit": browser_test.OUTLIER_SHARE,
        "frame": frame, "settings": settings, "kinds": kinds, "texturings": texturings,
        "miss_unforgiven": unforgiven, "forgiven_pixels": len(forgiven)}
    print("     %s: miss %.5f (r %.5f g %.5f b %.5f), fp16 rounding explains %.5f; %d pixels; without the "
          "post-scatter step forgiven (%d pixels) %.5f"
          % (what, miss, per_channel[0], per_channel[1], per_channel[2], fp16_explained, len(filtered), len(forgiven),
             unforgiven))
    if not single:
        out["per_profile"] = {}
        for name, px in per_profile.items():
            m, pc, fp = miss_of(web, native, colour, px, forgiven)
            small, outlier, big = tone_mapped(web, native, px)
            out["per_profile"][name] = {"pixels": len(px), "miss": m, "miss_per_channel": pc, "fp16_explained": fp,
                                        "share_beyond_small": small, "share_beyond_outlier": outlier, "largest_levels": big}
            print("     %s: miss %.5f (r %.5f g %.5f b %.5f), fp16 rounding explains %.5f; %d pixels, largest %d levels"
                  % (name, m, pc[0], pc[1], pc[2], fp, len(px), big))
    check(miss <= MISS_BOUND, "%s: the pass's output against the native output: miss %.5f (<= %.2f)" % (what, miss, MISS_BOUND))
    for name, p in out.get("per_profile", {}).items():
        check(p["miss"] <= MISS_BOUND, "%s: %s's miss %.5f (<= %.2f)" % (what, name, p["miss"], MISS_BOUND))
    # The check's own test: the native side with a scattering distance 5 % off (every profile's
    # scale) must fail the bound.
    wrong_dir = native_dir + "-scale-1.05"
    os.makedirs(wrong_dir, exist_ok=True)
    for name in ("colour.f32", "depth.f32", "profile.u8", "albedo.u8"):
        shutil.copyfile(os.path.join(native_dir, name), os.path.join(wrong_dir, name))
    wrong_fields = [v * 1.05 if k % PROFILE_FLOATS == 3 else v for k, v in enumerate(fields)]
    check(native_run(native_apply, wrong_dir, dict(params, fields=wrong_fields)) is not None,
          "%s: the check's own test: sss_three_native_apply with the scale 5 %% off ran" % what)
    wrong_native = floats(wrong_dir, "native.f32")
    wrong_miss = miss_of(web, wrong_native, colour, filtered, forgiven)[0]
    out["miss_scale_1_05"] = wrong_miss
    if not single:
        for name, px in per_profile.items():
            out["per_profile"][name]["miss_scale_1_05"] = miss_of(web, wrong_native, colour, px, forgiven)[0]
        print("     the scale 5 %% off, per profile: %s" % ", ".join(
            "%s %.4f" % (name, v["miss_scale_1_05"]) for name, v in out["per_profile"].items()))
    check(wrong_miss > MISS_BOUND, "%s: the check's own test: the scale 5 %% off natively: miss %.4f (> %.2f)"
          % (what, wrong_miss, MISS_BOUND))
    for name, p in out.get("per_profile", {}).items():
        check(p["miss_scale_1_05"] > MISS_BOUND, "%s: the check's own test for %s: miss %.4f (> %.2f)"
              % (what, name, p["miss_scale_1_05"], MISS_BOUND))
    check(small_share <= browser_test.SMALL_SHARE,
          "%s, tone-mapped: %.4f%% of filtered pixels beyond %d levels (<= %.2f%%)"
          % (what, 100 * small_share, browser_test.SMALL_LEVELS, 100 * browser_test.SMALL_SHARE))
    check(outlier_share <= browser_test.OUTLIER_SHARE,
          "%s, tone-mapped: %.4f%% of filtered pixels beyond %d levels (<= %.2f%%; largest %d)"
          % (what, 100 * outlier_share, browser_test.OUTLIER_LEVELS, 100 * browser_test.OUTLIER_SHARE, largest))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--site", required=True, help="the folder the package was installed into")
    parser.add_argument("--native-apply", help="sss_three_native_apply: the check against the native frame")
    parser.add_argument("--chromium", default=shutil.which("chromium") or "chromium")
    parser.add_argument("--out", help="where the images and results.json go (default: a temporary folder)")
    parser.add_argument("--screenshot", help="also save the example page's screenshot (split view) here")
    parser.add_argument("--frames", type=int, default=5, help="frames timed with and without the pass (median)")
    parser.add_argument("--timeout", type=float, default=300)
    args = parser.parse_args()
    if shutil.which(args.chromium) is None:
        print("SKIP: no Chromium (Debian: chromium; scripts/install-deps.sh test)")
        return 77
    if not os.path.isfile(os.path.join(args.site, EXAMPLE)):
        print("SKIP: the package is not installed in %s (web/three/test/run_three_test.sh installs it)" % args.site)
        return 77
    out_dir = args.out or tempfile.mkdtemp(prefix="sss-three-test-")
    os.makedirs(out_dir, exist_ok=True)
    results = {"width": WIDTH, "height": HEIGHT}
    start = time.monotonic()
    status = 0
    server = cdp.StaticServer(args.site)
    browser = cdp.Chromium(args.chromium)
    try:
        browser.open(server.url + EXAMPLE + "?hold")
        browser.wait_for("window.sssExample && (sssExample.holding || sssExample.failed)", timeout=args.timeout)
        browser.evaluate("import('/test/checks.js').then((m) => { window.checks = m; return true; })")
        run(browser, args, out_dir, results)
    except Failure:
        status = 1
    finally:
        browser.close()
        server.close()
    results["seconds"] = round(time.monotonic() - start, 1)
    with open(os.path.join(out_dir, "results.json"), "w") as f:
        json.dump(results, f, indent=2)
    print("results and images: " + out_dir)
    return status


if __name__ == "__main__":
    sys.exit(main())
