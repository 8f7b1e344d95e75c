"""The served viewer's x-t slice (viewer/serve_xt.py, viewer_serve.js; issue 47 item 4), checked in the browser by
test_viewer_browser.py's served part: the button renders the chosen CSV row's frames and the target's, the page
shows the picture with its caption, and the picture's slice panel is, frame by frame, the chosen image row of the
registered frames the raytracer wrote (decoded from the page's image, compared with the EXR files through the
display mapping of motion_loop.py), the columns within the registration margin left out. Screenshot:
ARTIFACTS/viewer_xt_1366.png."""
import base64
import io
import os
import sys


def xt_checks(d, check, wait, source, artifacts, row, image_row=16, frames=4):
    sys.path.insert(0, source)
    import numpy as np
    from PIL import Image
    from analysis.aliaslab_analysis.charts.motion_loop import display
    from analysis.aliaslab_analysis.io.exr import read_exr
    options = d.execute_script("return [...document.querySelectorAll('#alv .alv-serve-row option')].map(o => o.text)")
    want = f"{row['sampler']}, {row['spp']} spp, {row['filter']} r={float(row['radius']):g} "
    index = next((i for i, o in enumerate(options) if o.startswith(want)), None)
    check(index is not None, f"the row {want.strip()} is offered ({options[:3]} ...)")
    if index is None:
        return
    d.execute_script("const q = (s) => document.querySelector('#alv ' + s); window.ALIASLAB_VIEWER.xt = null; "
                     "q('.alv-serve-row').value = String(arguments[0]); q('.alv-serve-xt-row').value = arguments[1]; "
                     "q('.alv-serve-xt-frames').value = arguments[2]; q('.alv-serve-xt').click()",
                     index, str(image_row), str(frames))
    done = "return !!window.ALIASLAB_VIEWER.xt || /failed/.test(document.querySelector('#alv .alv-serve-status').textContent)"
    ok = wait(done) or wait(done) or wait(done)
    j = d.execute_script("return window.ALIASLAB_VIEWER.xt")
    status = d.execute_script("return document.querySelector('#alv .alv-serve-status').textContent")
    check(ok and j is not None, f"the server answers the x-t slice ({status})")
    if not j:
        return
    shown = wait("const i = document.querySelector('#alv .alv-xt-out img'); return !!i && i.complete && i.naturalWidth > 0")
    caption = d.execute_script("const c = document.querySelector('#alv .alv-xt-caption'); return c ? c.textContent : ''")
    check(shown and f"image row {image_row} (from the top) in {frames} frames" in caption,
          f"the page shows the x-t slice and says what it is ('{caption[:80]}')")
    paths = j["paths"]["method"]
    check(len(paths) == frames and j["labels"][1][0].startswith(f"{row['sampler']} {row['spp']} spp {row['filter']}"),
          f"{frames} frames of the chosen row ({j['labels'][1]})")
    src = d.execute_script("return document.querySelector('#alv .alv-xt-out img').src")
    png = np.asarray(Image.open(io.BytesIO(base64.b64decode(src.split(",", 1)[1]))).convert("RGB"))
    m, (sx, sy), (x0, y0) = j["margin"], j["scale"], j["origin"]
    worst = 0
    for t, p in enumerate(paths):
        img = read_exr(p)
        truth = display(img[image_row, m:img.shape[1] - m, :3])
        seen = png[y0 + t * sy + sy // 2, x0:x0 + truth.shape[0] * sx:sx]
        worst = max(worst, int(np.abs(seen.astype(int) - truth.astype(int)).max()))
    check(worst == 0, f"the slice shown is row {image_row} of each registered frame the raytracer wrote "
          f"(largest 8-bit difference {worst})")
    check(all(os.path.isfile(p) for p in j["paths"]["target"]), "the target's frames are beside them")
    d.execute_script("document.querySelector('#alv .alv-serve').scrollIntoView()")
    d.save_screenshot(os.path.join(artifacts, "viewer_xt_1366.png"))
