"""One scene's section of the report: its table of the lowest errors, its charts, the contact sheet, the
images of the best and the worst method, and where the error sits on screen (error spectra)."""
import html
import os

import numpy as np

from ..charts import figures, spectra
from ..io.study_rows import components
from .elements import figure
from .findings import method_name


def method_image(images, scene, r):
    """Paths (image, error image) of a row's seed-0 reconstruction, or None when the sweep wrote none."""
    folder = os.path.join(images, figures.slug(scene))
    stem = f"{r['sampler']}-spp{int(r['spp'])}-{r['filter_name']}-r{r['radius']:g}-{r['reconstruction']}"
    candidates = [stem]
    if r["prefilter"] not in ("none", ""):
        candidates = [f"{stem}-{r['prefilter']}", f"{stem}-prefilter-{r['prefilter']}"]
    for c in candidates:
        p = os.path.join(folder, c + ".png")
        if os.path.isfile(p):
            return p, os.path.join(folder, c + "-error.png")
    return None


TABLE_TOP = 5  # rows equivalent to the best listed per spp level (the rest counted)


def error_cell(r):
    if bool(r.get("deterministic", False)):
        return f"{r['error']:.3g} (deterministic)"
    se = r["error_se"]
    return f"{r['error']:.3g}" + (f" &plusmn; {se:.1g}" if np.isfinite(se) else "")


def alignment(r):
    """The fixed grid's error over K sub-pixel camera offsets (align_* columns), when the CSV has it."""
    a = r.get("align_mse_target", np.nan)
    if not bool(r.get("deterministic", False)) or not np.isfinite(a):
        return ""
    return (f"; over {int(r['align_offsets'])} camera offsets: mean {a:.3g} &plusmn; {r['align_mse_target_se']:.1g}, "
            f"sd {r['align_mse_target_sd']:.2g} ({a / r['error']:.3g}x this alignment)")


def standing(r):
    """The row against the scene's best: ratio, interval and verdict (stats/effect.py); the fixed grid's
    alignment beside it."""
    return _standing(r) + alignment(r)


def _standing(r):
    if r["best"]:
        return "best" + (" (deterministic)" if bool(r.get("deterministic", False)) else "")
    if not np.isfinite(r["ratio"]):
        return "undetermined"
    how = {"bootstrap": "; heavy-tailed, bootstrap over seeds", "linear": "; error not told from zero"}
    return (f"{r['ratio']:.3g}x [{r['ci_low']:.3g}-{r['ci_high']:.3g}] {r['verdict']}"
            + how.get(r["interval"], ""))


def scene_table(sd, ranked=None, margin=None):
    """HTML table of the rows equivalent to the scene's best at each spp level (stats/effect.py), with their
    terms; the fixed grid's best row beside them, with its verdict; flagged rows marked."""
    from ..stats import effect, equivalence
    margin = effect.MARGIN if margin is None else margin
    ranked = equivalence.per_scene(sd, margin) if ranked is None else ranked
    terms = components(sd)
    extra = [(c, l) for c, l in (("blurred_mse", "blurred mse"), ("flip", "FLIP"),
                                 ("lowfreq_error", "low-frequency share &plusmn; se"),
                                 ("mean_spp", "mean spp spent")) if c in sd.columns]
    rows = []
    for spp, g in ranked.groupby("spp", sort=True):
        top = g[g["verdict"] == effect.EQUIVALENT].sort_values("ratio")
        det = g[g["deterministic"].astype(bool) & ~g.index.isin(top.head(TABLE_TOP).index)]
        shown = [r for _, r in top.head(TABLE_TOP).iterrows()] + [r for _, r in det.nsmallest(1, "error").iterrows()]
        for r in shown:
            name = html.escape(method_name(r)) + (" <i>(flagged)</i>" if r["flagged"] == 1 else "")
            cells = [name, str(int(spp)), error_cell(r), standing(r)]
            for c, _ in terms:
                v = f"{r[c]:.2g}"
                if c == "aliasing" and r["aliasing_zero"]:
                    v += " (0 within error)"
                cells.append(v)
            for c, _ in extra:
                v = f"{r[c]:.3g}"
                se = r.get(c + "_se", np.nan)
                if c == "lowfreq_error" and np.isfinite(se) and not bool(r.get("deterministic", False)):
                    v += f" &plusmn; {se:.1g}"
                cells.append(v)
            cells.append(f"{r['cost']:.3g}" + (f" &plusmn; {r['cost_se']:.1g}" if np.isfinite(r["cost_se"]) else ""))
            rows.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
        if len(top) > TABLE_TOP:
            rows.append(f"<tr><td colspan='4'>and {len(top) - TABLE_TOP} more equivalent at {int(spp)} spp</td></tr>")
    head = (["method", "spp", "error &plusmn; se", "against the best: ratio [95 %], verdict"]
            + [html.escape(l) for _, l in terms] + [l for _, l in extra] + ["time (ms)"])
    return (f"<p>At each spp level the methods equivalent to the scene's best (within {100 * margin:g} %, the "
            "interval's upper end below the margin), and the fixed grid's best row (deterministic, ranked like any "
            "method). The rows share this scene's references; the interval counts their part for both rows.</p>"
            "<table><tr>" + "".join(f"<th>{h}</th>" for h in head) + "</tr>" + "".join(rows) + "</table>")


def spectrum_section(page_dir, scene, sd, spec, charts_dir, images, embed):
    """Where the error sits on screen. An overview chart of every sampler's error spectrum at one
    spp, then, at 4 and 16 spp, an independent and a correlated sampler side by side (error images, their
    spectra, mse, blurred mse, FLIP). Says so instead of failing when spectra or images are absent."""
    head = "<h4>Where the error sits on screen</h4>"
    if spec is None:
        return ""  # said once above the scenes (scene_notes)
    if not (spec["scene"] == str(scene)).any():
        return (head + "<p class='note'>No error spectra for this scene (the study CSV has no "
                "<code>spectra/</code> files beside it: written by sweeps since issue 22).</p>")
    spec = spec[spec["scene"] == str(scene)]
    levels = sorted(int(x) for x in spec["spp"].unique())
    parts = [head, f"<p>Radially averaged power spectra of the per-seed error images (I<sub>k</sub> &minus; G), "
             f"frequency in cycles per pixel; the dotted line is a quarter of Nyquist "
             f"({spectra.CUTOFF:g} cycles/pixel), below which <code>lowfreq_error</code> counts the error's "
             "energy. White error is flat; error moved to high frequencies (what the correlated samplers aim "
             "for) rises to the right. "
             "Definitions: docs/spectrum.md.</p>"]
    spp0 = spectra.pick_spp(levels, 16)
    overview = spectra.chart(spec, scene, spp0, spectra.chart_path(charts_dir, scene, spp0))
    if overview:
        parts.append(figure(page_dir, overview, f"Error spectra of every sampler at {spp0} spp.", embed))
    ind, corr = spectra.pick_samplers(spec["sampler"].unique())
    if ind is None or not corr:
        parts.append("<p class='note'>Side-by-side comparison omitted: the study needs an independent and a "
                     "correlated sampler (<code>zsobol</code> or <code>bluenoise-dither:BASE</code>).</p>")
        return "\n".join(p for p in parts if p)
    pair = [ind, corr[0]]
    has_flip = "flip" in sd.columns and np.isfinite(sd["flip"].to_numpy(dtype=float)).any()
    has_blur = "blurred_mse" in sd.columns
    if not has_flip:
        parts.append("<p class='note'>FLIP is not shown: this study CSV has no <code>flip</code> column.</p>")
    shown = [s for s in (4, 16) if s in levels] or levels[:2]
    filt, radius, recon = spectra.common_method(spec)
    for spp in shown:
        rows = sd[(sd["spp"] == spp) & (sd["filter_name"] == filt) & (sd["radius"] == float(radius))
                  & (sd["reconstruction"] == recon) & (sd["prefilter"].astype(str) == "none")]
        cells, pics = [], []
        for sampler in pair:
            r = rows[rows["sampler"] == sampler]
            if not len(r):
                continue
            r = r.iloc[0]
            vals = [f"mse {r['mse']:.3g}" + (" (deterministic)" if bool(r.get("deterministic", False)) else
                                             f" &plusmn; {r['mse_se']:.1g}" if "mse_se" in r and
                                             np.isfinite(r["mse_se"]) else "")]
            if has_blur:
                vals.append(f"blurred mse {r['blurred_mse']:.3g}")
            if "lowfreq_error" in r:
                se = r.get("lowfreq_error_se", np.nan)
                vals.append(f"low-frequency share {r['lowfreq_error']:.3g}"
                            + (f" &plusmn; {se:.1g}" if np.isfinite(se) else ""))
            if has_flip:
                vals.append(f"FLIP {r['flip']:.3g}")
            cells.append(f"<tr><td>{html.escape(sampler)}</td>" + "".join(f"<td>{v}</td>" for v in vals) + "</tr>")
            found = method_image(images, scene, r)
            if found:
                pics.append(figure(page_dir, found[1], f"{html.escape(sampler)}, {spp} spp: signed error of "
                                   "seed 0 (red too bright, blue too dark)", embed))
        png = spectra.chart(spec, scene, spp, spectra.chart_path(charts_dir, scene, spp, "spectrum_pair"),
                            samplers=pair, title=f"{scene}: {pair[0]} vs {pair[1]} at {spp} spp")
        if png:
            pics.append(figure(page_dir, png, f"Their error spectra at {spp} spp.", embed, cls="spec"))
        pics = [p for p in pics if p]
        parts.append(f"<h5>{spp} spp: {html.escape(pair[0])} (independent) vs {html.escape(pair[1])} "
                     f"(correlated), {html.escape(filt)} r={float(radius):g}</h5>")
        if cells:
            parts.append("<table>" + "".join(cells) + "</table>")
        if pics:
            parts.append("<div class='pair'>" + "".join(pics) + "</div>")
        elif os.path.isdir(images):
            parts.append("<p class='note'>No images for these rows (run the sweep with <code>--images</code>).</p>")
    return "\n".join(p for p in parts if p)


def scene_notes(images, spec):
    """What holds for every scene, said once above them instead of in each."""
    notes = []
    if not os.path.isdir(images):
        notes.append("This study kept no per-configuration images (a large sweep writes none unless given "
                     "<code>--images</code>): each scene shows its tables and charts, no renders.")
    if spec is None:
        notes.append("No error spectra: the study CSV has no <code>spectra/</code> files beside it (written by "
                     "sweeps since issue 22; not committed for the studies in results/), so where the error sits "
                     "on screen is told by the <code>lowfreq_error</code> and <code>blurred_mse</code> columns of "
                     "the tables alone.")
    return "".join(f"<p class='note'>{n}</p>" for n in notes)


def scene_section(page_dir, scene, sd, charts_dir, images, embed, spec=None, ranked=None, margin=None):
    s = figures.slug(scene)
    parts = [f"<h3 id='scene-{html.escape(s)}'>{html.escape(scene)}</h3>", scene_table(sd, ranked, margin)]

    def chart(kind, caption, toc=None):
        return figure(page_dir, os.path.join(charts_dir, f"{kind}_{s}.png"), caption, embed,
                      anchor=f"{kind}-{s}", toc=toc or kind.replace("_", " "))
    parts.append(chart("decomposition", "Where the error comes from: noise, aliasing and blur stacked, the cross "
                       "term hatched (negative terms left of 0), the total with &plusmn;2 standard errors.",
                       "decomposition"))
    parts.append(chart("radius", "Error (solid), noise (dashed) and blur (dotted) against the radius, one panel "
                       "per filter. The radius is each kernel's width: every shape is stretched or squeezed to it, "
                       "so below a filter's natural radius (box 0.5, tent 1, gaussian 1.5, mitchell, catmullrom and "
                       "blackmanharris 2, lanczos and hann 3) the kernel is a squeezed copy of itself (Lanczos and "
                       "Hann at r &le; 2: a three-lobe sinc in less than three pixels, sharper and with deeper "
                       "negative lobes), not a narrower window of the same kernel. Noise and blur then need not "
                       "move the usual way with r. One y range for all panels; degenerate points (weight sums near "
                       "zero) at the top edge, in red.", "radius trade-off"))
    parts.append(chart("convergence", "Convergence with spp (slopes only over at least three spp levels)."))
    parts.append(chart("speed_accuracy", "Error against the target vs time per image; the front (the points no "
                       "other point beats in both error and time) is numbered and listed; hollow: flagged; "
                       "crosses: the fixed grid (deterministic, ranked like any method).",
                       "error vs time"))
    parts.append(chart("heatmap", "Error over sampler x filter x radius, one panel per spp level; degenerate cells "
                       "(weight sums near zero) hatched and kept out of the colour scale.", "heatmap"))
    if os.path.isfile(os.path.join(charts_dir, f"blur_curve_{s}.png")):
        parts.append(chart("blur_curve", "The eye's low-pass: the share of each sampler's error left after a "
                           "Gaussian blur of sigma 0.5-4 px, beside white noise's curve (sum of the kernel's squared "
                           "weights); below it the error sits at high screen frequencies (blue).", "blur curve"))
    sheet = os.path.join(images, f"contact-{s}.png")
    if os.path.isfile(sheet):
        caption = "Contact sheet: zoomed crops of the hardest region."
        txt = os.path.join(images, f"contact-{s}.txt")
        if os.path.isfile(txt):
            with open(txt, encoding="utf-8", errors="replace") as f:
                caption = "Contact sheet: " + html.escape(f.readline().strip())
        parts.append(figure(page_dir, sheet, caption, embed, cls="sheet"))
    ok = sd[(sd["flagged"] == 0) & np.isfinite(sd["error"].to_numpy(dtype=float))]
    if len(ok):
        top = ok[ok["spp"] == ok["spp"].max()]
        pics = []
        target = os.path.join(images, s, "reference-area.png")
        pics.append(figure(page_dir, target, "pixel-area reference" + (" (the target)" if set(
            sd["target"].astype(str)) <= {"box:0.5", "area"} else ""), embed))
        for what, r in (("best", top.loc[top["error"].idxmin()]), ("worst", top.loc[top["error"].idxmax()])):
            found = method_image(images, scene, r)
            if found:
                label = f"{what}: {html.escape(method_name(r))}, {int(r['spp'])} spp, error {r['error']:.2g}"
                pics.append(figure(page_dir, found[0], label, embed))
                pics.append(figure(page_dir, found[1], f"{what}: signed error (red too bright, blue too dark)",
                                   embed))
        pics = [p for p in pics if p]
        if len(pics) > 1:
            parts.append("<div class='pix'>" + "".join(pics) + "</div>")
    spectra_html = spectrum_section(page_dir, scene, sd, spec, charts_dir, images, embed)
    if spectra_html:
        parts.append(f"<div id='spectra-{html.escape(s)}' data-toc='error spectra'></div>" + spectra_html)
    return "\n".join(p for p in parts if p)
