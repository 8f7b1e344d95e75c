// The viewer's panels (loaded after viewer_kit.js, before viewer.js): one figure per shown method (canvas drawn in
// the current mode with zoom and pan, its CSV row's numbers, the pixel readout) and the colour bar.
// window.ALIASLAB_VIEWER_PANELS(ctx) returns {panel, readout, colourBar, zoom}; ctx = {S (the viewer's state),
// D () (the scene's data), cur () (the current configuration), root, VIEW (canvas size), draw ()}.
(function () {
  "use strict";
  const K = window.ALIASLAB_VIEWER_KIT, {el, fmt, at, mean, shownValue, diverging, magma} = K;

  window.ALIASLAB_VIEWER_PANELS = function (ctx) {
    const {S, D, cur, root, VIEW, draw} = ctx;

    function missing(c, p) {
      const fig = el("figure", {class: "alv-panel", "data-config": c.id});
      const cv = el("canvas", {width: VIEW, height: VIEW}), g = cv.getContext("2d");
      g.fillStyle = "#ddd"; g.fillRect(0, 0, VIEW, VIEW); g.fillStyle = "#333"; g.font = "14px sans-serif";
      const lines = [""];
      for (const w of p.why.split(" ")) if ((lines[lines.length - 1] + " " + w).length > 44) lines.push(w); else lines[lines.length - 1] += " " + w;
      lines.forEach((line, k) => g.fillText(line.trim(), 20, VIEW / 2 - 10 + 20 * k));
      fig.appendChild(cv);
      fig.appendChild(el("figcaption", {}, `${c.sampler}, ${c.spp} spp, ${c.filter} r=${c.radius}`));
      return fig;
    }

    function paint(p, scale) {  // an off-screen canvas of the panel's pixels in the current mode
      const off = el("canvas", {width: p.img.w, height: p.img.h}), octx = off.getContext("2d");
      const out = octx.createImageData(p.img.w, p.img.h), g = (v) => 255 * Math.max(0, Math.min(1, v));
      for (let i = 0; i < p.img.w * p.img.h; ++i) {
        let rgb;
        if (S.mode === "error") rgb = diverging((mean(p.img, i) - mean(p.tgt, i)) / scale);
        else if (S.mode === "flip") rgb = magma(at(p.flip, i, 0));
        else { const im = S.mode === "image" ? p.img : S.mode === "ref" ? p.ref : p.tgt; rgb = [0, 1, 2].map((ch) => g(at(im, i, ch))); }
        out.data.set([rgb[0], rgb[1], rgb[2], 255], 4 * i);
      }
      octx.putImageData(out, 0, 0);
      return off;
    }

    function blit(cv) {
      const g = cv.getContext("2d");
      g.setTransform(1, 0, 0, 1, 0, 0); g.fillStyle = "#777"; g.fillRect(0, 0, VIEW, VIEW);
      g.setTransform(S.zoom, 0, 0, S.zoom, -S.ox * S.zoom, -S.oy * S.zoom);
      g.imageSmoothingEnabled = false;
      g.drawImage(cv._off, 0, 0);
    }

    function caption(c, p) {
      const row = c.rows[S.target] || {}, cap = el("figcaption");
      cap.appendChild(el("b", {}, c.sets.includes("exr") ? `${c.sampler} (your EXR)` : `${c.sampler}, ${c.spp} spp, ${c.filter} r=${c.radius}`));
      const seedNote = S.mode === "flip" ? " (FLIP map: seed 0)" : p.seed !== S.seed ? ` (only seed ${p.seed} held)` : "";
      cap.appendChild(el("span", {class: "alv-seed"}, ` seed ${S.mode === "flip" ? 0 : p.seed}` + seedNote));
      const dl = el("div", {class: "alv-values"});
      const item = (col, label) => {
        if (col in row) dl.appendChild(el("span", {"data-col": col, "data-value": String(row[col])}, `${label} ${fmt(row[col])}`));
      };
      dl.appendChild(document.createTextNode(`against ${S.target}: `));
      item("mse_target", "mse_target");
      if (row.deterministic) dl.appendChild(el("span", {class: "alv-det"}, " (deterministic: one image, no standard error)"));
      else item("mse_target_se", " \u00b1");
      dl.appendChild(el("br"));
      item("aliasing", "aliasing"); item("noise", " noise"); item("blur", " blur"); item("cross", " cross");
      dl.appendChild(el("br")); item("flip", "FLIP"); item("cpu_ms", " cpu ms"); item("flagged", " flagged");
      cap.appendChild(dl);
      if (c.why && c.why.length) cap.appendChild(el("div", {class: "alv-why", title: c.why.join("; ")},
        c.why[0] + (c.why.length > 1 ? ` (+${c.why.length - 1} more reasons: hover)` : "")));
      cap.appendChild(el("div", {class: "alv-readout"}, "point at a pixel for its value"));
      return cap;
    }

    function panel(c, p, scale, main) {
      if (p.missing) return missing(c, p);
      const fig = el("figure", {class: "alv-panel" + (main ? " alv-main" : ""), "data-config": c.id});
      const cv = el("canvas", {width: VIEW, height: VIEW});
      cv._p = p; cv._off = paint(p, scale);
      blit(cv);
      attachPointer(cv);
      fig.appendChild(cv);
      fig.appendChild(caption(c, p));
      return fig;
    }

    function attachPointer(cv) {
      let drag = null;
      const local = (ev) => { const r = cv.getBoundingClientRect(); return [(ev.clientX - r.left) * VIEW / r.width, (ev.clientY - r.top) * VIEW / r.height]; };
      cv.addEventListener("mousemove", (ev) => {
        const [mx, my] = local(ev);
        if (drag) {
          S.ox = drag[2] - (mx - drag[0]) / S.zoom; S.oy = drag[3] - (my - drag[1]) / S.zoom;
          for (const x of root.querySelectorAll(".alv-panel canvas")) if (x._off) blit(x);
          return;
        }
        const x = Math.floor(S.ox + mx / S.zoom), y = Math.floor(S.oy + my / S.zoom);
        S.hover = [x, y]; readout(x, y);
      });
      cv.addEventListener("mousedown", (ev) => { S.engaged = true; drag = [...local(ev), S.ox, S.oy]; });
      window.addEventListener("mouseup", () => { drag = null; });
      cv.addEventListener("wheel", (ev) => { ev.preventDefault(); zoom(ev.deltaY < 0 ? 1.25 : 0.8); }, {passive: false});
    }

    function zoom(f) { S.zoom = Math.max(VIEW / 512, Math.min(64, S.zoom * f)); draw(); }

    function readout(x, y) {
      const d = D();
      for (const fig of root.querySelectorAll(".alv-panel")) {
        const p = fig.querySelector("canvas")._p, out = fig.querySelector(".alv-readout");
        if (!out) continue;
        if (!p || x < 0 || y < 0 || x >= p.img.w || y >= p.img.h) { out.textContent = "outside the image"; continue; }
        const i = y * p.img.w + x, gx = S.region === "crop" ? x + d.crop.x : x, gy = S.region === "crop" ? y + d.crop.y : y;
        const vals = [0, 1, 2].slice(0, p.img.c).map((ch) => at(p.img, i, ch));
        out.textContent = "";
        const attrs = {"data-x": gx, "data-y": gy, "data-value": vals.join(","), "data-step": String(p.img.step)};
        if (p.flip) attrs["data-flip"] = String(at(p.flip, i, 0));
        out.appendChild(el("span", attrs,
          `pixel (${gx}, ${gy}): value ${shownValue(p.img, i)} (\u00b1${(p.img.step / 2).toPrecision(2)} stored), target ` +
          `${shownValue(p.tgt, i)}, error ${(mean(p.img, i) - mean(p.tgt, i)).toFixed(4)}` + (p.img.c > 1 ? " (mean of R, G, B)" : "") +
          (p.ref ? `, own reference ${shownValue(p.ref, i)}` : "") +
          (p.flip ? `, FLIP (seed 0) ${at(p.flip, i, 0).toFixed(3)}` : "")));
      }
    }

    function colourBar(scale) {
      const cv = root.querySelector(".alv-bar"), g = cv.getContext("2d"), w = cv.width;
      for (let i = 0; i < w; ++i) {
        const t = i / (w - 1);
        const rgb = S.mode === "error" ? diverging(2 * t - 1) : S.mode === "flip" ? magma(t) : [255 * t, 255 * t, 255 * t];
        g.fillStyle = `rgb(${rgb.map(Math.round).join(",")})`; g.fillRect(i, 0, 1, cv.height);
      }
      root.querySelector(".alv-bar-label").textContent = S.mode === "error"
        ? `signed error I \u2212 T against ${S.target}: blue ${fmt(-scale)} (too dark), white 0, red +${fmt(scale)} (too bright); ` +
          `scale: ${D().scaleHow} (${cur().spp} spp), larger errors saturate`
        : S.mode === "flip" ? `FLIP against ${S.target}: black 0 (no visible difference) to pale yellow 1 (largest); ` + (D().flipHow || "")
        : "value: black 0, white 1 (values outside [0, 1] saturate; the readout gives them)";
    }

    return {panel, readout, colourBar, zoom};
  };
})();
