// The comparison viewer (analysis/aliaslab_analysis/viewer): one per page, in the element #alv whose data-base is
// the folder of the per-scene data files (export.py) and data-scenes their list. A scene's file is loaded by a
// <script> element when the scene is opened (works from file://); its images are PNG data URIs holding values
// (value = lo + q (hi - lo) / (2^bits - 1)), decoded once through a canvas. Ids starting with "w" (whole images,
// FLIP maps against the non-primary targets) are in the scene's second file (d.wholeFile), loaded the same way
// the first time one of them is shown; it calls ALIASLAB_VIEWER_WHOLE(scene, images). Panels: the current method and the
// pinned ones, drawn with the same mode, seed, region, zoom and pan; the numbers beside each are its CSV row's.
// Loaded after viewer_kit.js (decoding, colour maps) and viewer_panels.js (the panels, readout and colour bar).
(function () {
  "use strict";
  const K = window.ALIASLAB_VIEWER_KIT, {el, byValue} = K;
  const root = document.getElementById("alv");
  if (!root) return;
  const base = root.dataset.base, scenes = JSON.parse(root.dataset.scenes);
  const data = {}, decoded = {}, $ = (sel) => root.querySelector(sel);
  const S = {scene: null, cfg: null, target: null, mode: "image", seed: 0, region: "crop", zoom: 0, ox: 0, oy: 0,
             pins: [], playing: null, engaged: false, hover: null};
  const MODES = [["image", "image"], ["ref", "own reference G"], ["target", "target T"],
                 ["error", "signed error I \u2212 T"],
                 ["flip", "FLIP map vs T"]];
  const DIMS = ["sampler", "spp", "filter", "radius"], VIEW = 384;
  window.ALIASLAB_VIEWER = {state: S, data: data};
  const D = () => data[S.scene];
  const cfgOf = (id) => D().configs.find((c) => c.id === id);
  const cur = () => cfgOf(S.cfg);
  const P = window.ALIASLAB_VIEWER_PANELS({S, D, cur, root, VIEW, draw: () => draw()});
  // select(id[, mode, region]): shows a configuration (the tests; a link to a method); false when it is not held
  window.ALIASLAB_VIEWER.select = (id, mode, region) => {
    if (!S.scene || !cfgOf(id)) return false;
    S.note = "";
    S.cfg = id; if (mode) S.mode = mode; if (region && region !== S.region) { S.region = region; S.zoom = 0; }
    draw(); return true;
  };
  window.ALIASLAB_VIEWER_ADD = function (d) {  // rows come as arrays in the order of d.rowColumns
    for (const c of d.configs)
      for (const t in c.rows) c.rows[t] = Object.fromEntries(d.rowColumns.map((k, i) => [k, c.rows[t][i]]));
    data[d.scene] = d;
    if (S.pending === d.scene) open(d.scene);
  };
  const later = {}, arrived = {};  // per scene: the promise of its second file, and its resolver
  window.ALIASLAB_VIEWER_WHOLE = function (scene, images) {
    if (!data[scene]) return;
    Object.assign(data[scene].images, images);
    if (arrived[scene]) arrived[scene]();
  };

  function load(scene) {
    if (data[scene]) return open(scene);
    S.pending = scene;
    $(".alv-status").textContent = "loading " + scene + " ...";
    const s = el("script", {src: base + scenes.find((x) => x.scene === scene).file});
    s.onerror = () => { $(".alv-status").textContent = "could not load the data of " + scene + " (" + s.src + ")"; };
    document.head.appendChild(s);
  }

  function loadLater(scene) {  // Promise: the scene's second file has been loaded (once per scene)
    if (later[scene]) return later[scene];
    const d = data[scene];
    later[scene] = new Promise((resolve, reject) => {
      if (!d.wholeFile) { reject(new Error("no whole-image file for " + scene)); return; }
      arrived[scene] = resolve;
      $(".alv-status").textContent = `loading the whole images of ${scene} (${(d.wholeBytes / 1e6).toFixed(1)} MB) ...`;
      const s = el("script", {src: base + d.wholeFile});
      s.onerror = () => { later[scene] = null; reject(new Error("could not load " + s.src)); };
      document.head.appendChild(s);
    });
    return later[scene];
  }

  function values(id) {  // Promise of {w, h, c, v: Float32Array (interleaved channels), step} of an image id
    const scene = S.scene, key = scene + "/" + id;
    if (decoded[key]) return decoded[key];
    const ready = data[scene].images[id] ? Promise.resolve() : loadLater(scene);
    decoded[key] = ready.then(() => {
      const e = data[scene].images[id];
      if (!e) throw new Error("no image " + id + " in the data of " + scene);
      return K.decode(e);
    });
    decoded[key].catch(() => { delete decoded[key]; });  // a failed load may be retried
    return decoded[key];
  }

  function open(scene) {
    S.pending = null; S.scene = scene;
    const d = D();
    S.target = d.primary;
    if (d.default && cfgOf(d.default.cfg)) {  // the answer's default view (export.py: answer.default_view)
      S.cfg = d.default.cfg; S.target = d.default.target || d.primary;
      S.pins = d.default.pins.filter((id) => cfgOf(id) && id !== S.cfg);
    } else {
      const low = d.levels[0], a = d.configs.filter((c) => c.spp === low);
      S.cfg = (a.find((c) => c.sampler === "jittered") || a[0] || d.configs[0]).id; S.pins = [];
    }
    S.seed = 0; S.zoom = 0; S.note = "";
    buildButtons(); draw();
  }

  function choose(dim, value) {  // the available configuration closest to the current one with dim = value
    const c = cur(), w = {sampler: 8, spp: 4, filter: 2, radius: 1};
    let best = null, score = -1;
    for (const x of D().configs) {
      if (String(x[dim]) !== String(value)) continue;
      let s = 0;
      for (const k of DIMS) if (k !== dim && String(x[k]) === String(c[k])) s += w[k];
      if (s > score) { score = s; best = x; }
    }
    if (best) { S.cfg = best.id; draw(); }
  }

  function step(dim, by) {  // filter and radius keep the sampler and spp: when they cannot, the status says why
    const c = cur(), keep = dim === "sampler" || dim === "spp" ? [] : ["sampler", "spp"];
    const pool = D().configs.filter((x) => keep.every((k) => String(x[k]) === String(c[k])));
    const vals = [...new Set(pool.map((x) => x[dim]))].sort(byValue);
    if (vals.length < 2) {
      S.note = `${c.sampler} at ${c.spp} spp is held with this ${dim} only (the viewer holds the methods the answer ` +
        `names: ${c.filter} r=${c.radius} is this sampler's); pick another ${dim} with the buttons to change the sampler too.`;
      draw(); return;
    }
    S.note = "";
    const i = vals.findIndex((v) => String(v) === String(c[dim]));
    const v = vals[(i + by + vals.length) % vals.length];
    if (!keep.length) { choose(dim, v); return; }
    const next = pool.filter((x) => String(x[dim]) === String(v));
    S.cfg = (next.find((x) => x.filter === c.filter || x.radius === c.radius) || next[0]).id; draw();
  }

  function buttonRow(label, items, onClick) {
    const row = el("div", {class: "alv-row"});
    row.appendChild(el("span", {class: "alv-label"}, label));
    for (const [value, text] of items) {
      const b = el("button", {type: "button", "data-value": String(value)}, text);
      b.onclick = () => { S.engaged = true; S.note = ""; onClick(value); };
      row.appendChild(b);
    }
    return row;
  }

  function buildButtons() {
    const d = D(), box = $(".alv-controls");
    box.textContent = "";
    for (const dim of DIMS) {
      const vals = [...new Set(d.configs.map((c) => c[dim]))].sort(byValue);
      const row = buttonRow(dim, vals.map((v) => [v, String(v)]), (v) => choose(dim, v));
      row.dataset.dim = dim;
      box.appendChild(row);
    }
    const t = buttonRow("target", d.targets.map((x) => [x, x]), (v) => { S.target = v; draw(); });
    t.dataset.dim = "target"; box.appendChild(t);
    const m = buttonRow("show", MODES, (v) => { S.mode = v; draw(); }); m.dataset.dim = "mode"; box.appendChild(m);
    const r = buttonRow("region", [["crop", "crop"], ["whole", "whole image"]], (v) => { S.region = v; S.zoom = 0; draw(); });
    r.dataset.dim = "region"; box.appendChild(r);
    const maxSeeds = Math.max(...d.configs.map((c) => c.seeds.length));
    const sd = buttonRow("seed", [...Array(maxSeeds).keys()].map((k) => [k, String(k)]), (v) => { S.seed = v; draw(); });
    sd.dataset.dim = "seed";
    const play = el("button", {type: "button", class: "alv-play"}, "play"); play.onclick = togglePlay; sd.appendChild(play);
    box.appendChild(sd);
    const pin = buttonRow("compare", [["pin", "pin this method (p)"], ["clear", "clear pins (x)"]],
                          (v) => { if (v === "pin") pinCurrent(); else { S.pins = []; draw(); } });
    box.appendChild(pin);
  }

  function pinCurrent() { if (!S.pins.includes(S.cfg)) S.pins.unshift(S.cfg); S.pins = S.pins.slice(0, 3); draw(); }
  function togglePlay() {
    if (S.playing) { clearInterval(S.playing); S.playing = null; }
    else S.playing = setInterval(() => { S.seed = (S.seed + 1) % Math.max(...D().configs.map((c) => c.seeds.length)); draw(); }, 600);
    $(".alv-play").textContent = S.playing ? "stop" : "play";
  }

  function imageId(c) {  // the shown configuration image id (seed S.seed where rendered, else seed 0) and its seed
    const seed = c.seeds.includes(S.seed) && S.region === "crop" ? S.seed : c.seeds[0];
    return [S.region === "crop" ? c.crop[String(seed)] : c.whole, seed];
  }

  async function panelData(c) {
    const d = D(), [id, seed] = imageId(c), t = d.targetImages[S.target][S.region];
    const r = c.ref && d.refs[c.ref] ? d.refs[c.ref][S.region] : null;
    const why = S.region === "whole" ? "whole image not stored for this one" : "crop not stored for this one";
    if (!id || !t) return {missing: true, seed: seed, why: why};
    if (S.mode === "ref" && !r) return {missing: true, seed: seed, why: "own reference not stored"};
    // FLIP maps (seed 0): the primary target's crop in the first file, every whole map in the second (cropped here)
    const fc = S.region === "crop" && c.flip ? c.flip[S.target] : null, fw = c.flipWhole ? c.flipWhole[S.target] : null;
    const wantFlip = S.mode === "flip" || fc;
    if (S.mode === "flip" && !fc && !fw) return {missing: true, seed: seed, why: "no FLIP map stored for this one"};
    try {
      const img = await values(id);
      const flip = !wantFlip ? null : fc ? await values(fc) : fw ? (S.region === "crop" ? K.cropOf(await values(fw), D().crop) : await values(fw)) : null;
      return {img: img, tgt: await values(t), ref: r ? await values(r) : null, flip: flip, seed: seed};
    } catch (err) {
      return {missing: true, seed: seed, why: String(err.message || err)};
    }
  }

  async function draw() {
    const d = D(), c = cur(), scale = d.scales[c.spp + "|" + S.target] || 0.1;
    for (const row of root.querySelectorAll(".alv-row")) {
      const dim = row.dataset.dim;
      for (const b of row.querySelectorAll("button[data-value]")) {
        const v = dim === "target" ? S.target : dim === "mode" ? S.mode : dim === "region" ? S.region
          : dim === "seed" ? S.seed : dim ? c[dim] : null;
        b.classList.toggle("on", v !== null && String(v) === b.dataset.value);
        if (dim === "seed") b.disabled = S.region !== "crop" || !c.seeds.includes(Number(b.dataset.value));
      }
    }
    const others = S.pins.filter((p) => p !== S.cfg);
    if (!others.length) S.ab = false;
    // A/B flicker (key b): the first panel shows the first pinned method in place of the current one
    const shown = [S.ab ? others[0] : S.cfg, ...others.slice(S.ab ? 1 : 0)];
    const panels = $(".alv-panels");
    const all = await Promise.all(shown.map((id) => panelData(cfgOf(id))));
    panels.textContent = "";
    const n = S.region === "crop" ? d.crop.size : d.width;
    if (!S.zoom) { S.zoom = VIEW / n; S.ox = 0; S.oy = 0; }
    all.forEach((p, i) => panels.appendChild(P.panel(cfgOf(shown[i]), p, scale, i === 0)));
    if (others.length) panels.firstChild.dataset.ab = S.ab ? "B" : "A";
    const abCap = panels.firstChild.querySelector("figcaption b");
    if (others.length && abCap) abCap.textContent = (S.ab ? "B: " : "A: ") + abCap.textContent + " (b flips A/B in place)";
    P.colourBar(scale);
    const crop = d.crop;
    $(".alv-status").textContent = (S.note ? S.note + " " : "") + (S.region === "crop" ? `crop ${crop.size} x ${crop.size} at (${crop.x}, ${crop.y}): ${crop.how}`
      : `whole image ${d.width} x ${d.height}, seed 0 (the whole images are loaded on demand, from ${d.wholeFile})`) +
      (d.default ? `. Opened on ${d.default.why}` : "") + `. Keys: \u2190 \u2192 sampler, \u2191 \u2193 spp, f filter, r radius, ` +
      "t target, 1-5 show, space next seed, a play, c crop/whole, p pin, x clear pins, b A/B flicker with the first pin, + - zoom, 0 reset; drag to pan, wheel to zoom.";
    if (S.hover) P.readout(S.hover[0], S.hover[1]);
  }

  document.addEventListener("mousedown", (ev) => { S.engaged = root.contains(ev.target); });
  document.addEventListener("keydown", (ev) => {
    if (!S.engaged || !S.scene || ev.ctrlKey || ev.metaKey || ev.altKey) return;
    const k = ev.key, acts = {
      ArrowRight: () => step("sampler", 1), ArrowLeft: () => step("sampler", -1),
      ArrowUp: () => step("spp", 1), ArrowDown: () => step("spp", -1),
      f: () => step("filter", 1), F: () => step("filter", -1), r: () => step("radius", 1), R: () => step("radius", -1),
      t: () => { const ts = D().targets; S.target = ts[(ts.indexOf(S.target) + 1) % ts.length]; draw(); },
      " ": () => { S.seed = (S.seed + 1) % Math.max(...D().configs.map((c) => c.seeds.length)); draw(); },
      a: togglePlay, c: () => { S.region = S.region === "crop" ? "whole" : "crop"; S.zoom = 0; draw(); },
      p: pinCurrent, x: () => { S.pins = []; draw(); }, b: () => { S.ab = !S.ab; draw(); }, "+": () => P.zoom(1.25), "=": () => P.zoom(1.25), "-": () => P.zoom(0.8),
      "0": () => { S.zoom = 0; draw(); },
      "1": () => { S.mode = "image"; draw(); }, "2": () => { S.mode = "ref"; draw(); },
      "3": () => { S.mode = "target"; draw(); }, "4": () => { S.mode = "error"; draw(); },
      "5": () => { S.mode = "flip"; draw(); },
    };
    if (acts[k]) { ev.preventDefault(); acts[k](); }
  });

  const bar = $(".alv-scenes");
  for (const s of scenes) {
    const b = el("button", {type: "button", "data-scene": s.scene}, s.scene);
    b.onclick = () => { S.engaged = true; for (const x of bar.children) x.classList.toggle("on", x === b); load(s.scene); };
    bar.appendChild(b);
  }
  const first = () => {
    if (S.scene || S.pending) return;
    bar.firstChild.classList.add("on"); load(scenes[0].scene);
  };
  if ("IntersectionObserver" in window) {
    const io = new IntersectionObserver((es) => { if (es.some((e) => e.isIntersecting)) { first(); io.disconnect(); } });
    io.observe(root);
  } else first();
})();
