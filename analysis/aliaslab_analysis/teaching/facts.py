"""The numbers of the teaching strand, every one computed from the study CSV (rows of the primary target,
weighted reconstruction, no pre-filtering):

  grid_scene   the scene where the fixed grid loses most against jittered with the box r = 0.5 at the lowest spp
               (largest mse_target ratio uniform / jittered), and in how many scenes the grid wins there
  degenerate   the configurations whose filter breaks the weighted average: undefined pixels (no sample with a
               non-zero weight) or noise at least DEGENERATE_NOISE times the box r = 0.5's with the same scene,
               sampler and spp (weight sums near zero amplify the noise); shown apart, never as "worst"
  extremes     per scene at the highest spp: the best row and the worst non-degenerate row
"""
import numpy as np

DEGENERATE_NOISE = 100.0


def primary_rows(df):
    target = str(df["target"].iloc[0]) if "box:0.5" not in set(df["target"].astype(str)) else "box:0.5"
    keep = ((df["target"].astype(str) == target) & (df["reconstruction"].astype(str) == "weighted")
            & (df["prefilter"].astype(str).isin(["none", ""])))
    return df[keep].copy(), target


def one(rows, **key):
    m = np.ones(len(rows), dtype=bool)
    for k, v in key.items():
        m &= (rows[k].to_numpy() == v) if not isinstance(v, float) else np.isclose(rows[k].to_numpy(dtype=float), v)
    r = rows[m]
    return r.iloc[0] if len(r) else None


def grid_scene(rows):
    """(scene, ratio, wins, scenes, spp): where the grid loses most to jittered (box r=0.5, lowest spp)."""
    spp = int(rows["spp"].min())
    out, wins, scenes = [], 0, 0
    for scene in sorted(rows["scene"].unique()):
        u = one(rows, scene=scene, sampler="uniform", spp=spp, filter_name="box", radius=0.5)
        j = one(rows, scene=scene, sampler="jittered", spp=spp, filter_name="box", radius=0.5)
        if u is None or j is None or not j["mse_target"] > 0:
            continue
        scenes += 1
        wins += int(u["mse_target"] < j["mse_target"])
        out.append((u["mse_target"] / j["mse_target"], scene))
    if not out:
        return None
    ratio, scene = max(out)
    return {"scene": scene, "ratio": float(ratio), "wins": wins, "scenes": scenes, "spp": spp}


def degenerate(rows):
    """{(scene, sampler, spp, filter, radius): reason} of the configurations that break the weighted average."""
    out = {}
    box = {(r.scene, r.sampler, int(r.spp)): float(r.noise) for r in
           rows[(rows["filter_name"] == "box") & np.isclose(rows["radius"].to_numpy(dtype=float), 0.5)].itertuples()}
    for r in rows.itertuples():
        key = (r.scene, r.sampler, int(r.spp), r.filter_name, float(r.radius))
        ref = box.get((r.scene, r.sampler, int(r.spp)))
        if int(r.undefined_pixels) > 0:
            out[key] = f"{int(r.undefined_pixels)} undefined pixels (no sample with a non-zero weight)"
        elif ref and ref > 0 and float(r.noise) >= DEGENERATE_NOISE * ref:
            out[key] = f"noise {float(r.noise) / ref:.0f} times the box r=0.5's (weight sums near zero)"
    return out


def extremes(rows, bad):
    """Per scene at the highest spp: (best row, worst non-degenerate row, degenerate rows) (deterministic rows out)."""
    spp = int(rows["spp"].max())
    out = {}
    for scene, sd in rows[(rows["spp"] == spp) & (rows["deterministic"].astype(int) == 0)].groupby("scene"):
        keys = [(r.scene, r.sampler, int(r.spp), r.filter_name, float(r.radius)) for r in sd.itertuples()]
        is_bad = np.array([k in bad for k in keys])
        ok = sd[~is_bad]
        if not len(ok):
            continue
        out[scene] = (ok.loc[ok["mse_target"].idxmin()], ok.loc[ok["mse_target"].idxmax()], sd[is_bad])
    return out, spp
