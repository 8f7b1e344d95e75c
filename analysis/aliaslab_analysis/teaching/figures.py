"""The teaching strand's pictures, drawn from the study's own images (the viewer's renders and the references):
the grid against jittered and Sobol' on one crop, an edge profile across filters, and the blur of a wide box."""
import numpy as np

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def best_window(score, size):
    """(x, y) of the size x size window with the largest sum of `score` (2-D)."""
    h, w = score.shape
    s = np.pad(score.cumsum(0).cumsum(1), ((1, 0), (1, 0)))
    best, at = -1.0, (0, 0)
    for y in range(0, h - size + 1, 2):
        for x in range(0, w - size + 1, 2):
            v = s[y + size, x + size] - s[y, x + size] - s[y + size, x] + s[y, x]
            if v > best:
                best, at = v, (x, y)
    return at


def shown(img):
    a = np.clip(img, 0, 1)
    return a[..., 0] if a.shape[2] == 1 else a[..., :3]


def trio(path, images, target, labels, size):
    """Images (top) and signed errors against the target (bottom) of the same crop; returns (x, y, scale)."""
    err0 = np.mean(images[0] - target, axis=2)
    x, y = best_window(err0 ** 2, size)
    crop = lambda a: a[y:y + size, x:x + size]
    errs = [np.mean(crop(i) - crop(target), axis=2) for i in images]
    scale = float(np.percentile(np.abs(np.concatenate([e.ravel() for e in errs])), 99)) or 1.0
    fig, ax = plt.subplots(2, len(images), figsize=(2.6 * len(images), 5.6), squeeze=False)
    for k, (img, e, lab) in enumerate(zip(images, errs, labels)):
        ax[0][k].imshow(shown(crop(img)), cmap="gray", vmin=0, vmax=1, interpolation="nearest")
        ax[0][k].set_title(lab, fontsize=9)
        im = ax[1][k].imshow(e, cmap="RdBu_r", vmin=-scale, vmax=scale, interpolation="nearest")
        for a in (ax[0][k], ax[1][k]):
            a.set_xticks([]), a.set_yticks([])
    ax[1][0].set_ylabel("signed error I - T", fontsize=8)
    cb = fig.colorbar(im, ax=list(ax[1]), orientation="horizontal", fraction=0.06, pad=0.04)
    cb.set_label(f"signed error (red too bright, blue too dark); +-{scale:.2g} = 99th percentile of |error|", fontsize=8)
    fig.savefig(path, dpi=80, bbox_inches="tight")
    plt.close(fig)
    return x, y, scale


def edge_point(img, margin=12):
    """(x, y) of the largest horizontal step of an image (channel mean), away from the borders."""
    g = np.mean(img, axis=2)
    d = np.abs(np.diff(g, axis=1))
    d[:, :margin] = 0
    d[:, -margin:] = 0
    d[:margin] = 0
    d[-margin:] = 0
    y, x = np.unravel_index(np.argmax(d), d.shape)
    return int(x), int(y)


def edge_profile(path, profiles, labels, x0, y, half=10):
    """Each filter's reference along row y from x0 - half to x0 + half (pixel values against x)."""
    fig, ax = plt.subplots(figsize=(6.4, 3.2))
    xs = np.arange(x0 - half, x0 + half + 1)
    for p, lab, style in zip(profiles, labels, ("-", "--", "-.", ":")):
        ax.plot(xs, p, style, marker="o", markersize=3, label=lab)
    ax.set_xlabel(f"pixel x along row y = {y}")
    ax.set_ylabel("pixel value (channel mean)")
    ax.axhline(min(profiles[0]), color="#999", lw=0.6)
    ax.axhline(max(profiles[0]), color="#999", lw=0.6)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.savefig(path, dpi=80, bbox_inches="tight")
    plt.close(fig)


def pair(path, images, labels, size, score):
    """Two images side by side on the window where `score` is largest."""
    x, y = best_window(score, size)
    fig, ax = plt.subplots(1, len(images), figsize=(2.8 * len(images), 3.0), squeeze=False)
    for k, (img, lab) in enumerate(zip(images, labels)):
        ax[0][k].imshow(shown(img[y:y + size, x:x + size]), cmap="gray", vmin=0, vmax=1, interpolation="nearest")
        ax[0][k].set_title(lab, fontsize=9)
        ax[0][k].set_xticks([]), ax[0][k].set_yticks([])
    fig.savefig(path, dpi=80, bbox_inches="tight")
    plt.close(fig)
    return x, y
