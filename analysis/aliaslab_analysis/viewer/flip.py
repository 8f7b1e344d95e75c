"""The viewer's FLIP maps: the per-pixel LDR-FLIP of an image against a target, computed by the project's own
imgdiff program (`imgdiff A B --flip-output MAP.exr`, the same flipMap as the sweep's flip column) and read back.
imgdiff appends a colour bar below the map (and widens the picture to at least 200 pixels); the map is its top
left width x height pixels, grey (R = G = B), FLIP in [0, 1].
The maps are kept in the work folder beside the images (a rerun computes only the missing ones)."""
import os
import subprocess
from concurrent.futures import ThreadPoolExecutor

from ..io import errors
from ..io.exr import read_exrs


def imgdiff_beside(raytracer):
    """The imgdiff program built beside the raytracer (build/bin)."""
    return os.path.join(os.path.dirname(os.path.abspath(raytracer)), "imgdiff")


def map_path(image, target_key):
    """Where the FLIP map of `image` against the target `target_key` (e.g. 'box:0.5') is kept."""
    return image[:-4] + ".flip-" + target_key.replace(":", "-") + ".exr"


def flip_maps(imgdiff, pairs, size, jobs=2):
    """pairs: (image path, target image path, map path), size: the images' (width, height); returns the
    (height, width) FLIP map of each pair (the picture's top left: its colour bar is at least 200 pixels wide),
    running imgdiff for the maps not yet in their files."""
    if not (os.path.isfile(imgdiff) and os.access(imgdiff, os.X_OK)):
        errors.fail(f"--imgdiff: {imgdiff}: not an executable program (build it: cmake --build build --target imgdiff)")

    def one(p):
        image, target, out = p
        if os.path.isfile(out):
            return None
        tmp = out[:-4] + ".partial.exr"
        run = subprocess.run([imgdiff, image, target, "--flip-output", tmp], capture_output=True, text=True)
        if run.returncode != 0 or not os.path.isfile(tmp):
            return f"{imgdiff} {image} {target}: {run.stderr.strip()[:300]}"
        os.replace(tmp, out)
        return None
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        failed = [e for e in pool.map(one, pairs) if e]
    if failed:
        errors.fail(f"{len(failed)} FLIP map(s) failed, first: {failed[0]}")
    return [m[:size[1], :size[0], 0] for m in read_exrs([p[2] for p in pairs])]
