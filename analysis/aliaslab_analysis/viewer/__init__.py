"""The comparison viewer of the page (issue 30): the study's own images side by side on the same region.

  plan.py     which configurations are shown (a subset chosen from the CSV) and the crop window
  render.py   renders them with the raytracer (the sweep's sampler, seed and filter: the same images)
  exr.py      reads EXR images through Debian's oiiotool
  export.py   checks each image against the CSV's per-seed mse_target and writes RESULTS/viewer/<scene>.js
  section.py  the page's section (viewer.js, viewer.css inline; the data loaded per scene when opened)
  cli.py      `python3 -m analysis viewer RESULTS --study CSV --raytracer build/bin/raytracer`
"""
