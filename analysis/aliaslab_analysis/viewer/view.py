"""The view the viewer opens on: the default view's configuration ids among those exported, and
the crop where its methods' mean images differ most relative to their noise (plan.crop_window)."""
import numpy as np

from .plan import crop_window, image_stem


def key_id(k):
    """The viewer's id of a configuration key (sampler, spp, filter, radius)."""
    return f"{k[0]}|{k[1]}|{k[2]}|{k[3]:g}"


def config_id(c):
    return key_id((c["sampler"], c["spp"], c["filter"], c["radius"]))


def choose_crop(plan, configs, seeds, n):
    """The crop (plan.crop_window) over the default view's methods at the lowest spp (else every method
    there): their mean images over the rendered seeds against the noise of those means."""
    low = [c for c in configs if c["spp"] == plan.levels[0]]
    view = [config_id(c) for c in low if config_id(c) in default_ids(plan)]
    chosen = [c for c in low if config_id(c) in view] if len(view) >= 2 else low
    chosen = chosen or configs
    means, noise = [], []
    for c in chosen:
        imgs = np.array([seeds[(image_stem(c, 0), k)].mean(axis=2) for k in c["seeds"]])
        means.append(imgs.mean(axis=0))
        noise.append(imgs.var(axis=0, ddof=1) / len(imgs) if len(imgs) > 1 else np.zeros(imgs.shape[1:]))
    with_noise = any(len(c["seeds"]) > 1 for c in chosen)
    x, y = crop_window(np.array(means), n, noise=np.array(noise) if with_noise else None)
    names = ", ".join(f"{c['sampler']} {c['filter']} r={c['radius']:g}" for c in chosen[:4]) + \
        (f" and {len(chosen) - 4} more" if len(chosen) > 4 else "")
    how = (f"the {n} x {n} window where the mean images (over {max(len(c['seeds']) for c in chosen)} seeds) of "
           f"{names} at {chosen[0]['spp']} spp differ most relative to their noise (the variance across the "
           "methods over the window, divided by the noise of the means there plus the image's average)")
    return x, y, how


def default_ids(plan):
    """The ids of the default view's methods (plan.default: answer.default_view)."""
    d = plan.default
    if not d:
        return []
    return [key_id(k) for k in [d["cfg"]] + d["pins"]]


def default_view(plan, out_configs):
    """{cfg, pins, why}: the view the viewer opens on (answer.default_view), its ids among those exported."""
    have = {c["id"] for c in out_configs}
    ids = [i for i in default_ids(plan) if i in have]
    if not ids:
        return None
    return {"cfg": ids[0], "pins": ids[1:], "why": plan.default["why"], "target": plan.default["target"]}


def holds_whole(plan, c):
    """Whether configuration c's whole image and whole FLIP maps are stored (plan.whole: a key of WHOLE)."""
    how = getattr(plan, "whole", "all")
    return how == "all" or config_id(c) in default_ids(plan) or (how == "answer" and "E" in c["sets"]) or \
        (how == "headline" and c.get("headline", False))
