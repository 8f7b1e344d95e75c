#!/usr/bin/python3
"""The comparison viewer in a real browser (issue 30): Debian's chromium, driven by python3-selenium through
chromium-driver, loads a page generated for a small study from file:// and checks that

  - the console has no error (level SEVERE);
  - a key press (ArrowRight: the next sampler) switches the method, and the picture drawn changes;
  - the readout of a pixel under the pointer equals that pixel of the configuration's image file (the EXR the
    raytracer wrote, read here with OpenImageIO's Python module, or oiiotool where it is missing), within half
    the stored step the viewer states;
  - every number beside an image equals its CSV row's value (the CSV read here with the csv module) to the
    three significant digits shown;
  - every link and script of the page resolves (anchors to an element of the page, files to a file);
  - the key 5 switches to the FLIP map: the picture changes, the colour bar is the FLIP ramp (coloured, not grey)
    labelled FLIP 0..1, and the FLIP readout of a pixel equals imgdiff's map (the EXR kept in the work folder)
    within half the 8-bit step;
  - the key t switches the FLIP map to a target other than the primary one (its map is in the scene's second
    data file, loaded on demand): the map is displayed and its readout equals imgdiff's map against that target;
  - the key c shows the whole image of a method other than the grid (also in the second file): it loads, and the
    readout of a pixel equals that pixel of the configuration's image file within half the stored step;
the view it opens on is the answer's default (three panels in one row at 1366 px); every method answer.csv calls
equivalent can be selected and its whole image and whole FLIP map load; the grid shows no standard error; f keeps
the sampler; b flips A/B in place; served (--serve) it renders a row not in the data with the CSV's per-seed
mse_target and readout, shows a user EXR's error map, and the x-t slice of a row over registered frames
(served_xt.py);
and writes screenshots at 1366 px wide to ARTIFACTS/viewer_1366.png and viewer_flip_1366.png.

  test_viewer_browser.py --sweep BIN --raytracer BIN --source REPO --artifacts DIR
Exit 77 (CTest: skipped) with the reason when chromium, chromium-driver or python3-selenium is missing."""
import argparse
import csv
import glob
import gzip
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.parse

from served_xt import xt_checks

SKIP = 77


def skip(why):
    print(f"SKIPPED: {why}")
    sys.exit(SKIP)


def browser():
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        skip("python3-selenium is not installed (README command (b) installs it)")
    chrome = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = shutil.which("chromedriver") or ("/usr/bin/chromedriver" if os.path.exists("/usr/bin/chromedriver") else None)
    if not chrome or not driver:
        skip("chromium or chromium-driver is not installed (README command (b) installs them)")
    o = webdriver.ChromeOptions()
    o.binary_location = chrome
    for a in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1366,1000",
              "--disable-gpu", "--force-device-scale-factor=1"):
        o.add_argument(a)
    o.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(driver), options=o)


def read_image(path):
    """(height, width, channels) values of an image file, row 0 at the top, read independently of the viewer."""
    try:
        import OpenImageIO as oiio
        buf = oiio.ImageBuf(path)
        return buf.get_pixels(oiio.FLOAT)
    except ImportError:
        sys.path.insert(0, ARGS.source)
        from analysis.aliaslab_analysis.io.exr import read_exr
        return read_exr(path)


def run(cmd, **kw):
    print("+", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, cwd=ARGS.source, **kw)


def csv_rows(path):
    """The rows of a CSV, gzipped (answer.csv.gz) or not."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:2] == b"\x1f\x8b":
        data = gzip.decompress(data)
    return list(csv.DictReader(io.StringIO(data.decode("utf-8"), newline="")))


def default_view_checks(d, check, wait):
    """The view opened first: the answer's default (three methods at the lowest spp), its panels side by side
    within the 1366 px window."""
    v = d.execute_script("const V = window.ALIASLAB_VIEWER, s = V.state, x = V.data[s.scene];"
                         "return [s.cfg, s.pins, x.default, x.levels[0]]")
    cfg, pins, default, low = v
    check(default is not None and cfg == default["cfg"] and pins == default["pins"] and len(pins) == 2,
          f"the viewer opens on the answer's default view ({cfg} beside {pins})")
    check(all(int(c.split("|")[1]) == low for c in [cfg] + pins), f"the default view is at the lowest spp ({low})")
    boxes = d.execute_script("return [...document.querySelectorAll('#alv .alv-panel')].map(f => "
                             "{const r = f.getBoundingClientRect(); return [r.left, r.right, r.top]})")
    check(len(boxes) == 3 and len({round(b[2]) for b in boxes}) == 1 and max(b[1] for b in boxes) <= 1366,
          f"the three default panels sit in one row within 1366 px ({boxes})")


def answer_checks(d, check, wait, page, work):
    """Every method answer.csv calls equivalent to the best can be selected, and its whole image and whole FLIP
    map load; the fixed grid shows no standard error; `f` keeps the sampler or says why; b flips A/B in place."""
    scene = d.execute_script("return window.ALIASLAB_VIEWER.state.scene")
    held = set(d.execute_script("return window.ALIASLAB_VIEWER.data[arguments[0]].configs.map(c => c.id)", scene))
    named = set()
    for r in csv_rows(os.path.join(page, "answer.csv.gz")):
        if r["verdict"] == "equivalent" and r["scope"] in ("all", scene) and r["reconstruction"] == "weighted":
            named.add(f"{r['sampler']}|{int(float(r['spp']))}|{r['filter']}|{float(r['radius']):g}")
    check(named and named <= held, f"every method answer.csv calls equivalent in {scene} is held "
                                   f"({len(named)}; missing {sorted(named - held)[:3]})")
    ok = 0
    for cid in sorted(named & held):
        for mode in ("image", "flip"):
            d.execute_script("window.ALIASLAB_VIEWER.select(arguments[0], arguments[1], 'whole')", cid, mode)
            loaded = wait("const f = document.querySelector('#alv .alv-main'); return f && f.dataset.config === "
                          f"'{cid}' && f.querySelector('.alv-readout') !== null")
            ok += bool(loaded)
    check(ok == 2 * len(named & held), f"{ok} whole images and whole FLIP maps of the equivalent methods load")
    d.execute_script("window.ALIASLAB_VIEWER.select(window.ALIASLAB_VIEWER.data[arguments[0]].default.cfg, "
                     "'image', 'crop')", scene)
    wait("return document.querySelector('#alv .alv-main .alv-readout') !== null")
    grid = d.execute_script("return window.ALIASLAB_VIEWER.data[arguments[0]].configs.filter(c => "
                            "Object.values(c.rows)[0].deterministic).map(c => c.id)", scene)
    if grid:
        d.execute_script("window.ALIASLAB_VIEWER.select(arguments[0])", grid[0])
        wait("return document.querySelector('#alv .alv-main .alv-readout') !== null")
        caption = d.find_element("css selector", "#alv .alv-main figcaption").text
        check("\u00b1" not in caption and "no standard error" in caption,
              f"the fixed grid ({grid[0]}) shows no standard error: '{caption[:90]}'")
    from selenium.webdriver.common.action_chains import ActionChains
    alone = d.execute_script("const cs = window.ALIASLAB_VIEWER.data[arguments[0]].configs; return (cs.find(c => "
                             "cs.filter(x => x.sampler === c.sampler && x.spp === c.spp).length === 1) || {}).id",
                             scene)
    if alone:  # a sampler held with one filter at its spp: f stays and says why
        d.execute_script("window.ALIASLAB_VIEWER.select(arguments[0])", alone)
        wait("return document.querySelector('#alv .alv-main .alv-readout') !== null")
    before = d.execute_script("return window.ALIASLAB_VIEWER.state.cfg")
    d.find_element("css selector", "#alv .alv-status").click()
    ActionChains(d).send_keys("f").perform()
    time.sleep(0.5)
    after = d.execute_script("return window.ALIASLAB_VIEWER.state.cfg")
    status = d.find_element("css selector", "#alv .alv-status").text
    check(after.split("|")[0] == before.split("|")[0] and (after != before or "held with this filter only" in status)
          and (not alone or (after == before and "held with this filter only" in status)),
          f"f keeps the sampler ({before} -> {after}) or says why ('{status[:80]}')")
    if not alone:  # no such sampler in this study: make one (the scene's data without the current sampler's other
        # configurations at its spp) and press f there
        d.execute_script("const V = window.ALIASLAB_VIEWER, d = V.data[V.state.scene], c = d.configs.find(x => x.id "
                         "=== V.state.cfg); d.configs = d.configs.filter(x => x === c || x.sampler !== c.sampler || "
                         "x.spp !== c.spp); V.select(c.id)")
        ActionChains(d).send_keys("f").perform()
        time.sleep(0.5)
        status = d.find_element("css selector", "#alv .alv-status").text
        check(d.execute_script("return window.ALIASLAB_VIEWER.state.cfg") == after and
              "held with this filter only" in status, f"f on a sampler held with one filter stays and says why "
                                                      f"('{status[:90]}')")
    d.execute_script("const s = window.ALIASLAB_VIEWER.state, x = window.ALIASLAB_VIEWER.data[s.scene].default;"
                     "s.pins = x.pins.slice(); window.ALIASLAB_VIEWER.select(x.cfg)")
    wait("return document.querySelectorAll('#alv .alv-panel .alv-readout').length === 3")
    first = "return document.querySelector('#alv .alv-main').dataset.config"
    a = d.execute_script(first)
    ActionChains(d).send_keys("b").perform()
    wait("return document.querySelectorAll('#alv .alv-panel .alv-readout').length === 2")
    b = d.execute_script(first)
    pins = d.execute_script("return window.ALIASLAB_VIEWER.state.pins")
    check(a != b and b == pins[0], f"b shows the first pinned method in the first panel ({a} -> {b})")
    ActionChains(d).send_keys("b").perform()
    wait("return document.querySelectorAll('#alv .alv-panel .alv-readout').length === 3")
    check(d.execute_script(first) == a, "b again shows the current method again")


def served_checks(d, check, wait, page, study, work, cache, rows):
    """The served viewer (serve.py): renders a CSV row the exported data does not hold (a seed past the
    flip-book's), its mse_target from the image equal to the CSV's per-seed value and its readout equal to the EXR
    the raytracer wrote; loads a user EXR and shows its error map against a chosen target."""
    held = set()
    for name in glob.glob(os.path.join(page, "viewer", "*.js")):
        with open(name, encoding="utf-8") as f:
            text = f.read()
        if text.startswith("ALIASLAB_VIEWER_ADD("):
            data = json.loads(text[len("ALIASLAB_VIEWER_ADD("):text.rstrip().rindex(")")])
            held |= {(data["scene"], c["id"], k) for c in data["configs"] for k in c["seeds"]}
    scene = sorted({r["scene"] for r in rows})[0]
    row = next(r for r in rows if r["scene"] == scene and r["reconstruction"] == "weighted" and
               (scene, f"{r['sampler']}|{r['spp']}|{r['filter']}|{float(r['radius']):g}", 3) not in held)
    mine = os.path.join(os.path.dirname(work), "mine.exr")
    shutil.copy(next(iter(glob.glob(os.path.join(work, "*", "*-seed0.exr")))), mine)
    proc = subprocess.Popen([sys.executable, "-m", "analysis", "viewer", page, "--study", os.path.join(study, "study.csv"),
                             "--raytracer", ARGS.raytracer, "--work", work, "--cache", cache, "--serve", "--port", "0",
                             "--exr", mine], cwd=ARGS.source, stdout=subprocess.PIPE, text=True,
                            env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))
    try:
        line = proc.stdout.readline()
        url = line.split(" on ")[1].split()[0] if " on http" in line else None
        check(url is not None, f"the server says where it serves ({line.strip()})")
        if not url:
            return
        d.get(url)
        d.execute_script("document.getElementById('alv').scrollIntoView()")
        check(wait("return !!window.ALIASLAB_VIEWER.served && !!document.querySelector('#alv .alv-serve')"),
              "the served page shows the render controls")
        d.execute_script("window.ALIASLAB_VIEWER.state.scene !== arguments[0] && "
                         "document.querySelector(`#alv [data-scene='${arguments[0]}']`).click()", scene)
        wait(f"return window.ALIASLAB_VIEWER.state.scene === '{scene}' && "
             "document.querySelector('#alv .alv-main .alv-readout') !== null")
        d.execute_script("window.ALIASLAB_VIEWER.serveRender({sampler: arguments[0], spp: arguments[1], filter: "
                         "arguments[2], radius: arguments[3], seed: 3}).then(j => window._served = j, "
                         "e => window._served = {error: String(e)})", row["sampler"], row["spp"], row["filter"],
                         row["radius"])
        check(wait("return !!window._served") or wait("return !!window._served"), "the server answers the render")
        got = d.execute_script("return window._served")
        seeds = {r["target"]: float(r["mse_target_seeds"].split(";")[3]) for r in rows
                 if (r["scene"], r["sampler"], r["spp"], r["filter"], r["radius"], r["reconstruction"]) ==
                 (scene, row["sampler"], row["spp"], row["filter"], row["radius"], "weighted")}
        ver = {t: mine_v for t, mine_v, _ in (got or {}).get("verified", [])}
        check(ver and set(ver) == set(seeds) and all(abs(ver[t] - seeds[t]) <= 1e-5 * abs(seeds[t]) for t in seeds),
              f"the row rendered on request ({row['sampler']} {row['spp']} spp {row['filter']} r={row['radius']} "
              f"seed 3) has the CSV's per-seed mse_target ({ver} vs {seeds}; {(got or {}).get('error')})")
        cid = (got or {}).get("config", {}).get("id")
        check(wait(f"return document.querySelector('#alv .alv-main').dataset.config === '{cid}' && "
                   "document.querySelector('#alv .alv-main .alv-readout') !== null"), f"{cid} is shown")
        canvas = d.find_element("css selector", "#alv .alv-main canvas")
        d.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
        from selenium.webdriver.common.action_chains import ActionChains
        ActionChains(d).move_to_element_with_offset(canvas, 7, -9).perform()
        time.sleep(0.3)
        span = d.find_element("css selector", "#alv .alv-main .alv-readout span")
        x, y = int(span.get_attribute("data-x")), int(span.get_attribute("data-y"))
        values = [float(v) for v in span.get_attribute("data-value").split(",")]
        img = read_image(got["config"]["path"])
        diffs = [abs(v - float(img[y, x, c])) for c, v in enumerate(values)]
        check(max(diffs) <= float(span.get_attribute("data-step")) / 2 + 1e-6,
              f"the served image's readout at ({x}, {y}) {values} equals the raytracer's EXR {img[y, x, :len(values)]}")
        # a user EXR, its error map against the second target
        d.execute_script("window._exr = null; window.ALIASLAB_VIEWER.serveExr('mine.exr').then(j => window._exr = j, "
                         "e => window._exr = {error: String(e)})")
        check(wait("return !!window._exr") or wait("return !!window._exr"), "the server answers the EXR")
        err = d.execute_script("return window._exr.error || null")
        check(err is None and wait("return document.querySelector('#alv .alv-main').dataset.config === 'exr:mine.exr'"),
              f"the user EXR is shown ({err})")
        targets = d.execute_script("return window.ALIASLAB_VIEWER.data[arguments[0]].targets", scene)
        d.execute_script("const V = window.ALIASLAB_VIEWER; V.state.target = arguments[0]; V.select('exr:mine.exr', "
                         "'error', 'crop')", targets[-1])
        wait("return document.querySelector('#alv .alv-main .alv-readout') !== null")
        label = d.find_element("css selector", "#alv .alv-bar-label").text
        canvas = d.find_element("css selector", "#alv .alv-main canvas")
        ActionChains(d).move_to_element_with_offset(canvas, 5, 5).perform()
        time.sleep(0.3)
        text = d.find_element("css selector", "#alv .alv-main .alv-readout span").text
        check(f"against {targets[-1]}" in label and "error" in text,
              f"the user EXR's error map against {targets[-1]} ('{label[:50]}', readout '{text[:80]}')")
        xt_checks(d, check, wait, ARGS.source, ARGS.artifacts, row)  # the x-t slice of the row (served_xt.py)
        logs = [e for e in d.get_log("browser") if e.get("level") == "SEVERE"]
        check(not logs, f"no console errors when served ({logs[:2]})")
        d.save_screenshot(os.path.join(ARGS.artifacts, "viewer_served_1366.png"))
    finally:
        proc.terminate()
        proc.wait(timeout=10)


def main():
    d = browser()
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.keys import Keys
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what, flush=True)
        if not ok:
            failures.append(what)

    tmp = tempfile.mkdtemp(prefix="aliaslab-viewer-browser-")
    try:
        study, page, work, cache = (os.path.join(tmp, x) for x in ("study", "page", "work", "cache"))
        run([ARGS.sweep, "--scenes", "scenes/checker_horizon.txt", "--size", "32", "32", "--samplers",
             "uniform,jittered,sobol", "--spp", "4,16", "--filters", "box,gaussian", "--radii", "0.5,1", "--seeds", "4",
             "--ref-spp", "256", "--target", "area,gaussian:1.5", "--cache", cache, "--out", study, "--no-images",
             "--quiet", "--threads", "2"])
        env = dict(os.environ, MPLBACKEND="Agg", PYTHONDONTWRITEBYTECODE="1")
        os.makedirs(page)
        run([sys.executable, "-m", "analysis", "viewer", page, "--study", os.path.join(study, "study.csv"),
             "--raytracer", ARGS.raytracer, "--work", work, "--cache", cache, "--flip-seeds", "2", "--whole", "answer",
             "--quiet"], env=env)
        run([sys.executable, "-m", "analysis", "report", page, "--study", os.path.join(study, "study.csv"),
             "--reuse-charts"], env=env, stdout=subprocess.DEVNULL)
        rows = csv_rows(os.path.join(study, "study.csv"))

        index = os.path.join(page, "index.html")
        d.get("file://" + index)
        d.execute_script("document.getElementById('alv').scrollIntoView()")
        wait = lambda js: next((True for _ in range(100) if d.execute_script(js) or time.sleep(0.1)), False)
        check(wait("return document.querySelectorAll('#alv .alv-panel canvas').length > 0"), "the viewer draws its panels")
        time.sleep(0.5)
        default_view_checks(d, check, wait)
        main_canvas = "return document.querySelector('#alv .alv-main canvas').toDataURL()"
        state = "return window.ALIASLAB_VIEWER.state.cfg"
        before_cfg, before_pic = d.execute_script(state), d.execute_script(main_canvas)
        d.find_element("css selector", "#alv .alv-status").click()  # engage the viewer's keys
        ActionChains(d).send_keys(Keys.ARROW_RIGHT).perform()
        time.sleep(1.0)
        after_cfg, after_pic = d.execute_script(state), d.execute_script(main_canvas)
        # each sampler is held at its own best filter and radius: the spp stays, the filter may follow the sampler
        check(after_cfg != before_cfg and after_cfg.split("|")[0] != before_cfg.split("|")[0]
              and after_cfg.split("|")[1] == before_cfg.split("|")[1],
              f"ArrowRight switches the sampler at the same spp ({before_cfg} -> {after_cfg})")
        check(after_pic != before_pic, "the displayed image changes with it")

        # the readout of one pixel against the configuration's image file
        canvas = d.find_element("css selector", "#alv .alv-main canvas")
        d.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
        size = canvas.size
        ActionChains(d).move_to_element_with_offset(canvas, size["width"] // 5, size["height"] // 7).perform()
        time.sleep(0.3)
        span = d.find_element("css selector", "#alv .alv-main .alv-readout span")
        x, y = int(span.get_attribute("data-x")), int(span.get_attribute("data-y"))
        stepsize = float(span.get_attribute("data-step"))
        shown = span.text.split("value ")[1].split(" (")[0].strip("()").split(", ")
        sampler, spp, filt, radius = after_cfg.split("|")
        seed = d.execute_script("return window.ALIASLAB_VIEWER.state.seed")
        exr = glob.glob(os.path.join(work, "*", f"{sampler}-spp{spp}-{filt}-r{radius}-seed{seed}.exr"))
        check(len(exr) == 1, f"the image file of {after_cfg} seed {seed} exists")
        if exr:
            img = read_image(exr[0])
            truth = [float(img[y, x, c]) for c in range(len(shown))]
            diffs = [abs(float(s) - t) for s, t in zip(shown, truth)]
            check(all(dv <= stepsize / 2 + 5e-5 for dv in diffs),
                  f"readout at ({x}, {y}) {shown} equals the file's {[round(t, 5) for t in truth]} within half the "
                  f"stored step {stepsize:.2g} (largest difference {max(diffs):.2g})")

        # every number beside an image against the CSV
        target = d.execute_script("return window.ALIASLAB_VIEWER.state.target")
        spans = d.find_elements("css selector", "#alv .alv-panel [data-col]")
        compared = 0
        for s in spans:
            cfg = s.find_element("xpath", "ancestor::figure").get_attribute("data-config").split("|")
            row = [r for r in rows if (r["sampler"], r["spp"], r["filter"], r["target"]) == (cfg[0], cfg[1], cfg[2], target)
                   and float(r["radius"]) == float(cfg[3]) and r["reconstruction"] == "weighted"]
            col = s.get_attribute("data-col")
            text = s.text.split()[-1].lstrip("\u00b1")
            ok = len(row) == 1 and float(text) == float(f"{float(row[0][col]):.3g}")
            compared += 1
            if not ok:
                check(False, f"{cfg} {col}: shown {text}, CSV {row[0][col] if row else 'no row'}")
        check(compared >= 6, f"{compared} numbers beside the images equal their CSV rows' values")

        logs = [e for e in d.get_log("browser") if e.get("level") == "SEVERE"]
        check(not logs, f"no console errors ({logs[:3]})")

        # every link and script resolves
        refs = d.execute_script("return [...document.querySelectorAll('a[href], link[href]')].map(a => "
                                "a.getAttribute('href')).concat([...document.querySelectorAll('script[src]')]"
                                ".map(s => s.getAttribute('src')))")
        check(any(r.endswith("viewer/viewer.js") for r in refs), "the viewer's script is a file beside the page")
        bad = []
        for h in refs:
            if h.startswith("#"):
                if not d.execute_script("return !!document.getElementById(arguments[0])", h[1:]):
                    bad.append(h)
            elif not h.startswith(("data:", "http:", "https:")):
                target_path = os.path.normpath(os.path.join(page, urllib.parse.unquote(h.split("#")[0])))
                if not os.path.exists(target_path):
                    bad.append(h)
            else:
                bad.append(h + " (outside the repository)") if h.startswith("http") else None
        check(not bad, f"all {len(refs)} links and scripts resolve ({bad[:5]})")

        os.makedirs(ARGS.artifacts, exist_ok=True)
        d.execute_script("document.getElementById('viewer').scrollIntoView()")
        time.sleep(0.3)
        shot = os.path.join(ARGS.artifacts, "viewer_1366.png")
        d.save_screenshot(shot)
        print(f"screenshot: {shot}")

        # the FLIP map mode: key 5
        before_pic = d.execute_script(main_canvas)
        d.find_element("css selector", "#alv .alv-status").click()
        ActionChains(d).send_keys("5").perform()
        time.sleep(1.0)
        check(d.execute_script("return window.ALIASLAB_VIEWER.state.mode") == "flip", "the key 5 shows the FLIP map")
        check(d.execute_script(main_canvas) != before_pic, "the displayed picture changes to the FLIP map")
        label = d.find_element("css selector", "#alv .alv-bar-label").text
        bar = d.execute_script("const c = document.querySelector('#alv .alv-bar').getContext('2d');"
                               "return [...c.getImageData(192, 6, 1, 1).data].slice(0, 3)")
        check("FLIP" in label and "0" in label and "1" in label and len(set(bar)) > 1,
              f"the FLIP colour bar is shown, coloured {bar}, labelled '{label[:60]}...'")
        canvas = d.find_element("css selector", "#alv .alv-main canvas")
        d.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
        ActionChains(d).move_to_element_with_offset(canvas, size["width"] // 5, size["height"] // 7).perform()
        time.sleep(0.3)
        span = d.find_element("css selector", "#alv .alv-main .alv-readout span")
        shown_flip = span.get_attribute("data-flip")
        cfg = d.execute_script(state).split("|")
        x, y = int(span.get_attribute("data-x")), int(span.get_attribute("data-y"))
        maps = glob.glob(os.path.join(work, "*", f"{cfg[0]}-spp{cfg[1]}-{cfg[2]}-r{cfg[3]}-seed0.flip-"
                                      f"{target.replace(':', '-')}.exr"))
        check(shown_flip is not None and len(maps) == 1, f"a FLIP readout ({shown_flip}) and imgdiff's map {maps}")
        if shown_flip is not None and maps:
            truth = float(read_image(maps[0])[y, x, 0])
            check(abs(float(shown_flip) - truth) <= 0.5 / 255 + 1e-6,
                  f"FLIP readout at ({x}, {y}) {float(shown_flip):.5f} equals imgdiff's map {truth:.5f} within half "
                  f"the 8-bit step")
        check(not [e for e in d.get_log("browser") if e.get("level") == "SEVERE"], "no console errors in FLIP mode")
        d.execute_script("document.getElementById('viewer').scrollIntoView()")
        time.sleep(0.3)
        shot = os.path.join(ARGS.artifacts, "viewer_flip_1366.png")
        d.save_screenshot(shot)
        print(f"screenshot: {shot}")

        # the FLIP map against a target other than the primary one: key t, the second file loaded on demand
        primary = d.execute_script("return window.ALIASLAB_VIEWER.data[window.ALIASLAB_VIEWER.state.scene].primary")
        scene = d.execute_script("return window.ALIASLAB_VIEWER.state.scene")
        check(not d.execute_script("return Object.keys(window.ALIASLAB_VIEWER.data[arguments[0]].images)"
                                   ".some(k => k.startsWith('w'))", scene),
              "the whole images and other targets' FLIP maps are not loaded with the scene")
        d.find_element("css selector", "#alv .alv-status").click()
        ActionChains(d).send_keys("t").perform()
        other = d.execute_script("return window.ALIASLAB_VIEWER.state.target")
        readout = "return document.querySelector('#alv .alv-main .alv-readout') !== null"
        check(other != primary and wait(readout), f"the FLIP map against {other} (not the primary {primary}) is shown")
        canvas = d.find_element("css selector", "#alv .alv-main canvas")
        d.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
        ActionChains(d).move_to_element_with_offset(canvas, -size["width"] // 6, size["height"] // 5).perform()
        time.sleep(0.3)
        span = d.find_element("css selector", "#alv .alv-main .alv-readout span")
        shown_flip, cfg = span.get_attribute("data-flip"), d.execute_script(state).split("|")
        x, y = int(span.get_attribute("data-x")), int(span.get_attribute("data-y"))
        maps = glob.glob(os.path.join(work, "*", f"{cfg[0]}-spp{cfg[1]}-{cfg[2]}-r{cfg[3]}-seed0.flip-"
                                      f"{other.replace(':', '-')}.exr"))
        check(shown_flip is not None and len(maps) == 1, f"a FLIP readout against {other} and imgdiff's map {maps}")
        if shown_flip is not None and maps:
            truth = float(read_image(maps[0])[y, x, 0])
            check(abs(float(shown_flip) - truth) <= 0.5 / 255 + 1e-6,
                  f"FLIP against {other} at ({x}, {y}) {float(shown_flip):.5f} equals imgdiff's map {truth:.5f}")

        # the whole image of a method other than the grid: key 1 (image), c (whole)
        ActionChains(d).send_keys("1").perform()
        time.sleep(0.5)
        if cfg[0] == "uniform":
            ActionChains(d).send_keys(Keys.ARROW_RIGHT).perform()
            time.sleep(0.5)
        ActionChains(d).send_keys("c").perform()
        cfg = d.execute_script(state)
        check(d.execute_script("return window.ALIASLAB_VIEWER.state.region") == "whole" and wait(readout),
              f"the whole image of {cfg} is loaded and shown")
        sampler, spp, filt, radius = cfg.split("|")
        check(sampler != "uniform", f"{cfg} is not the grid")
        canvas = d.find_element("css selector", "#alv .alv-main canvas")
        d.execute_script("arguments[0].scrollIntoView({block: 'center'})", canvas)
        ActionChains(d).move_to_element_with_offset(canvas, size["width"] // 4, -size["height"] // 3).perform()
        time.sleep(0.3)
        span = d.find_element("css selector", "#alv .alv-main .alv-readout span")
        x, y = int(span.get_attribute("data-x")), int(span.get_attribute("data-y"))
        stepsize = float(span.get_attribute("data-step"))
        values = [float(v) for v in span.get_attribute("data-value").split(",")]
        exr = glob.glob(os.path.join(work, "*", f"{sampler}-spp{spp}-{filt}-r{radius}-seed0.exr"))
        check(len(exr) == 1, f"the image file of {cfg} seed 0 exists")
        if exr:
            img = read_image(exr[0])
            check(0 <= x < img.shape[1] and 0 <= y < img.shape[0], f"the pointer is on the whole image ({x}, {y})")
            truth = [float(img[y, x, c]) for c in range(len(values))]
            diffs = [abs(v - t) for v, t in zip(values, truth)]
            check(max(diffs) <= stepsize / 2 + 1e-6,
                  f"whole-image readout at ({x}, {y}) {values} equals the file's {[round(t, 5) for t in truth]} "
                  f"within half the stored step {stepsize:.2g}")
        check(not [e for e in d.get_log("browser") if e.get("level") == "SEVERE"], "no console errors after the "
              "on-demand loads")
        shot = os.path.join(ARGS.artifacts, "viewer_whole_1366.png")
        d.save_screenshot(shot)
        print(f"screenshot: {shot}")
        answer_checks(d, check, wait, page, work)
        served_checks(d, check, wait, page, study, work, cache, rows)
        check(not [e for e in d.get_log("browser") if e.get("level") == "SEVERE"], "no console errors at the end")
    finally:
        d.quit()
        shutil.rmtree(tmp, ignore_errors=True)
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sweep", required=True)
    ap.add_argument("--raytracer", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--artifacts", required=True)
    ARGS = ap.parse_args()
    sys.exit(main())
