"""Reading and checking the files the analysis takes in, the lowest layer (imports nothing of the package).

  errors.py      bad input: InputError, exit 2 with a message naming the file or option
  study_csv.py   reading a study CSV: load_study(path) -> (DataFrame, notes)
  study_rows.py  the columns load_study adds (deterministic, cost, per-seed values), the targets, the error
                 decomposition's terms a CSV holds
  text_file.py   a text file's text whether or not it is gzipped (the committed studies are study.csv.gz)
  csv_tables.py  reading the experiments' small CSVs (convergence, pointsets, filterprofile), checked
  exr.py         reading EXR images through Debian's oiiotool
"""
