"""The teaching strand of the page: facts.py (the numbers, from the CSV), figures.py (the
pictures, from the study's images), build.py (the HTML fragment RESULTS/viewer/teaching.html), negative.py (the negative control's
record), cli.py (the `teaching` command, run after `viewer`)."""
