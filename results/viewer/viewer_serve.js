// The viewer served on localhost (serve.py: `python3 -m analysis viewer RESULTS --study CSV --serve`): when the page
// comes over http and /alv-api/info answers, a row of controls renders any configuration of the CSV with the
// raytracer and that row's seed (the server checks its mse_target against the CSV's per-seed value, as the export
// does) or loads an EXR the user named (--exr); each arrives as a configuration of its own (whole image, crop,
// whole FLIP maps against every target), shown as the current method with the previous one pinned beside it; or
// the x-t slice of the chosen row (an image row over registered frames of a moving camera, beside the target's).
(function () {
  "use strict";
  const V = window.ALIASLAB_VIEWER, root = document.getElementById("alv");
  if (!V || !root || !location.protocol.startsWith("http")) return;
  let info = null, n = 0;
  const el = window.ALIASLAB_VIEWER_KIT.el;
  const box = el("div", {class: "alv-row alv-serve"}), say = el("span", {class: "alv-serve-status"});

  function add(scene, res) {  // res: {config, images: {whole, crop, flip: {target: entry}}, rowColumns}
    const d = V.data[scene], id = () => "s" + (n++), c = Object.assign({}, res.config);
    const whole = id(), crop = id();
    d.images[whole] = res.images.whole; d.images[crop] = res.images.crop;
    c.whole = whole; c.crop = {[String(c.seeds[0])]: crop}; c.flip = {}; c.flipWhole = {};
    for (const t in res.images.flip) { const k = id(); d.images[k] = res.images.flip[t]; c.flipWhole[t] = k; }
    for (const t in c.rows) c.rows[t] = Object.fromEntries(res.rowColumns.map((k, i) => [k, c.rows[t][i]]));
    if (c.ref && !d.refs[c.ref]) c.ref = null;
    const old = d.configs.findIndex((x) => x.id === c.id);
    if (old >= 0) d.configs.splice(old, 1);
    d.configs.push(c);
    const S = V.state;
    if (S.cfg !== c.id && !S.pins.includes(S.cfg)) S.pins.unshift(S.cfg);
    S.pins = S.pins.filter((p) => p !== c.id).slice(0, 3);
    V.select(c.id);
    return c;
  }

  function request(what, params) {  // Promise of the server's answer, its configuration shown
    const S = V.state, d = V.data[S.scene];
    const q = new URLSearchParams(Object.assign({scene: S.scene, x: d.crop.x, y: d.crop.y, n: d.crop.size}, params));
    say.textContent = what === "render" ? "rendering with the raytracer ..." : "loading ...";
    return fetch("/alv-api/" + what + "?" + q).then((r) => r.json()).then((j) => {
      if (j.error) throw new Error(j.error);
      add(S.scene, j);
      say.textContent = j.verified ? "rendered; mse_target from the image equals the CSV's per-seed value: " +
        j.verified.map(([t, mine, csv]) => `${t} ${mine.toPrecision(6)} (CSV ${csv.toPrecision(6)})`).join(", ")
        : "loaded: mse_target " + Object.entries(j.mse_target).map(([t, v]) => `${t} ${v.toPrecision(4)}`).join(", ");
      return j;
    }).catch((e) => { say.textContent = "failed: " + (e.message || e); throw e; });
  }
  V.serveRender = (row) => request("render", row);  // row: {sampler, spp, filter, radius, seed}
  V.serveExr = (name) => request("exr", {name: name});

  // The x-t slice (serve_xt.py): an image row over frames of a moving camera registered to the content, beside
  // the primary target's; its controls in a row of their own, the picture below them (enlarged, pixels kept sharp).
  const xtBox = el("div", {class: "alv-row alv-xt"}), xtOut = el("div", {class: "alv-xt-out"});
  V.serveXt = (row) => {  // row: {sampler, spp, filter, radius, seed, row, frames}
    const q = new URLSearchParams(Object.assign({scene: V.state.scene}, row));
    say.textContent = "rendering the frames with the raytracer ...";
    return fetch("/alv-api/xt?" + q).then((r) => r.json()).then((j) => {
      if (j.error) throw new Error(j.error);
      xtOut.textContent = "";
      const img = el("img", {src: j.png, alt: "x-t slice", style: "image-rendering:pixelated;max-width:100%"});
      img.onload = () => { img.style.width = Math.min(2, Math.floor(900 / img.naturalWidth) || 1) * img.naturalWidth + "px"; };
      xtOut.append(img, el("div", {class: "alv-xt-caption"}, `x-t slice: image row ${j.row} (from the top) in ` +
        `${j.frames} frames of the camera moving (${j.motion.join(", ")}) px per frame, frame 0 at the top, ` +
        `registered to the content (columns within ${j.margin} px of a side left out). Vertical streaks: steady; ` +
        "slanted or crawling texture: shimmer; speckle: noise. Below: each row minus the mean of the rows."));
      say.textContent = "x-t slice of " + j.labels[1].join(", ");
      V.xt = j;  // the last answer (its frame paths: what the browser test compares the picture with)
      return j;
    }).catch((e) => { say.textContent = "failed: " + (e.message || e); throw e; });
  };

  function build() {
    box.textContent = "";
    box.appendChild(el("span", {class: "alv-label"}, "render"));
    const rows = el("select", {class: "alv-serve-row"}), seed = el("input", {type: "number", min: "0", value: "0",
      class: "alv-serve-seed", style: "width:4em"});
    const fill = () => {
      const have = (info.scenes[V.state.scene] || []);
      if (rows.dataset.scene === V.state.scene) return;
      rows.dataset.scene = V.state.scene; rows.textContent = "";
      have.forEach(([s, spp, f, r, k], i) => rows.appendChild(el("option", {value: String(i)},
        `${s}, ${spp} spp, ${f} r=${r} (${k} seeds)`)));
    };
    rows.addEventListener("focus", fill); rows.addEventListener("mousedown", fill); fill();
    const go = el("button", {type: "button"}, "render this row (raytracer)");
    go.onclick = () => {
      fill();
      const [s, spp, f, r] = info.scenes[V.state.scene][Number(rows.value)];
      V.serveRender({sampler: s, spp: spp, filter: f, radius: r, seed: seed.value}).catch(() => {});
    };
    box.append(rows, " seed ", seed, go);
    const d0 = V.data[V.state.scene], y = el("input", {type: "number", min: "0", class: "alv-serve-xt-row",
      style: "width:4em", value: String(d0 && d0.crop ? d0.crop.y + Math.floor(d0.crop.size / 2) : 0)});
    const frames = el("input", {type: "number", min: "2", max: "64", value: "16", class: "alv-serve-xt-frames",
      style: "width:4em"});
    const xtGo = el("button", {type: "button", class: "alv-serve-xt"}, "x-t slice");
    xtGo.onclick = () => {
      fill();
      const [s, spp, f, r] = info.scenes[V.state.scene][Number(rows.value)];
      V.serveXt({sampler: s, spp: spp, filter: f, radius: r, seed: seed.value, row: y.value, frames: frames.value})
        .catch(() => {});
    };
    xtBox.textContent = "";
    xtBox.append(el("span", {class: "alv-label"}, "x-t"), "the row chosen above: image row ", y, " over ", frames,
      " frames ", xtGo);
    if (info.exrs.length) {
      const ex = el("select", {class: "alv-serve-exr"});
      for (const name of info.exrs) ex.appendChild(el("option", {value: name}, name));
      const load = el("button", {type: "button"}, "load your EXR");
      load.onclick = () => V.serveExr(ex.value).catch(() => {});
      box.append(" ", ex, load);
    }
    box.appendChild(say);
    root.insertBefore(box, root.querySelector(".alv-panels"));
    root.insertBefore(xtBox, root.querySelector(".alv-panels"));
    root.insertBefore(xtOut, root.querySelector(".alv-panels"));
  }

  fetch("/alv-api/info").then((r) => (r.ok ? r.json() : null)).then((j) => {
    if (!j || !j.scenes) return;
    info = j; V.served = true;
    const wait = setInterval(() => { if (V.state.scene) { clearInterval(wait); build(); } }, 100);
  }).catch(() => {});
})();
