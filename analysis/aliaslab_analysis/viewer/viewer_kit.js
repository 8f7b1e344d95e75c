// The viewer's kit (loaded before viewer.js): stateless helpers shared by viewer.js, viewer_panels.js and
// viewer_serve.js, in window.ALIASLAB_VIEWER_KIT. Stored images are PNG data URIs holding values
// (value = lo + q (hi - lo) / (2^bits - 1), 16-bit values split over two images or two channels); decode()
// turns an entry {src, src2?, w, h, c, bits, lo, hi} into {w, h, c, v: Float32Array (interleaved channels), step}.
(function () {
  "use strict";
  const el = (tag, attrs, text) => {
    const e = document.createElement(tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  };
  const fmt = (v) => v === null || v === undefined ? "n/a"
    : typeof v === "number" ? (Number.isInteger(v) ? String(v) : Number(v).toPrecision(3)) : String(v);

  function pixelsOf(src, w, h) {  // Promise of the RGBA bytes of a PNG data URI
    return new Promise((resolve, reject) => {
      const img = new Image();
      img.onload = () => {
        const c = el("canvas", {width: w, height: h}), ctx = c.getContext("2d");
        ctx.drawImage(img, 0, 0);
        resolve(ctx.getImageData(0, 0, w, h).data);
      };
      img.onerror = () => reject(new Error("cannot decode a stored image"));
      img.src = src;
    });
  }

  function decode(e) {  // Promise of the values of a stored entry
    return Promise.all([pixelsOf(e.src, e.w, e.h), e.src2 ? pixelsOf(e.src2, e.w, e.h) : null]).then(([a, b]) => {
      const n = e.w * e.h, v = new Float32Array(n * e.c), k = (e.hi - e.lo) / (Math.pow(2, e.bits) - 1);
      for (let i = 0; i < n; ++i)
        for (let ch = 0; ch < e.c; ++ch) {
          const q = e.bits === 8 ? a[4 * i + ch] : e.c === 1 ? a[4 * i] * 256 + a[4 * i + 1] : a[4 * i + ch] * 256 + b[4 * i + ch];
          v[i * e.c + ch] = e.lo + q * k;
        }
      return {w: e.w, h: e.h, c: e.c, v: v, step: k};
    });
  }

  function cropOf(im, k) {  // the window k = {x, y, size} of a whole image's values
    const v = new Float32Array(k.size * k.size * im.c);
    for (let y = 0; y < k.size; ++y)
      v.set(im.v.subarray(((k.y + y) * im.w + k.x) * im.c, ((k.y + y) * im.w + k.x + k.size) * im.c), y * k.size * im.c);
    return {w: k.size, h: k.size, c: im.c, v: v, step: im.step};
  }

  const at = (im, i, ch) => im.v[i * im.c + Math.min(ch, im.c - 1)];
  const mean = (im, i) => { let s = 0; for (let ch = 0; ch < 3; ++ch) s += at(im, i, ch); return s / 3; };
  const shownValue = (im, i) => im.c === 1 ? at(im, i, 0).toFixed(4)
    : "(" + [0, 1, 2].map((ch) => at(im, i, ch).toFixed(4)).join(", ") + ")";

  function diverging(t) {  // t in [-1, 1]: blue, white, red
    t = Math.max(-1, Math.min(1, t));
    const [r, g, b] = t < 0 ? [33, 102, 172] : [178, 24, 43], a = Math.abs(t);
    return [255 + (r - 255) * a, 255 + (g - 255) * a, 255 + (b - 255) * a];
  }

  function magma(t) {  // t in [0, 1]: black, purple, orange, pale yellow (a magma-like ramp for FLIP)
    const stops = [[0, 0, 4], [81, 18, 124], [183, 55, 121], [252, 137, 97], [252, 253, 191]];
    t = Math.max(0, Math.min(1, t)) * (stops.length - 1);
    const i = Math.min(stops.length - 2, Math.floor(t)), f = t - i;
    return [0, 1, 2].map((k) => stops[i][k] + (stops[i + 1][k] - stops[i][k]) * f);
  }

  const byValue = (a, b) => (typeof a === "number" ? a - b : a < b ? -1 : 1);
  window.ALIASLAB_VIEWER_KIT = {el, fmt, decode, cropOf, at, mean, shownValue, diverging, magma, byValue};
})();
