"""The target as a choice the reader sees: what each target favours, and
why the pixel-area target itself aliases; the answer under each target is the answer table's column."""


def targets_text(s, science):
    """HTML: a paragraph on the targets of the study (s: findings.Study)."""
    text = ("<p>The error of a method is measured against a target image, and the target is a choice: the "
            "pixel-area image (<code>box:0.5</code>) favours the box filter at r = 0.5 by construction, and "
            "itself aliases (its box response lets frequencies above Nyquist through: replica rings on the zone "
            "plate, moir&eacute; at the Siemens star centre; "
            f"<a href='{science}'>docs/science.md</a>). A Gaussian and a band-limited target weigh blur and "
            "aliasing differently: at high spp most of the error against them is blur, so a ranking there mostly "
            "measures how close a filter's kernel is to the target's (the trade-off charts below show noise plus "
            "aliasing against blur for every filter).</p>")
    if len(s.targets) < 2:
        text += ("<p class='note'>This study carries one target only: its answer holds for that target. "
                 "Studies run with several targets show each in its own column.</p>")
    return text
