"""The comparison viewer of the page: the study's own images side by side on the same region.

  answer.py   the methods the answer names (as answer.csv: equivalent to the best, best of each sampler) and
              the default view
  plan.py     which configurations are shown (those answer.py names, the teaching trio) and the crop window
  view.py     the view opened first (the answer's default) and its crop
  serve.py    --serve: the page on localhost, any CSV row rendered on request, the user's EXRs
  render.py   renders them with the raytracer (the sweep's sampler, seed and filter: the same images)
  encoding.py an image's values as a PNG data URI (8 or 16 bits over its own range) and back
  export.py   checks each image against the CSV's per-seed mse_target and writes RESULTS/viewer/<scene>.js
              (loaded when the scene is opened) and <scene>_whole.js (whole images, whole FLIP maps against
              every target: loaded when asked for)
  xt_slice.py x-t slices of the motion study: one image row over the frames, rendered and drawn
(the page's section of the viewer is report/viewer_section.py; the teaching strand, built from these renders,
is the teaching package)
  cli.py      `python3 -m analysis viewer RESULTS --study CSV --raytracer build/bin/raytracer [--serve]`
"""
