"""How an Ensemble and a PreprocessResult show themselves in Jupyter (``_repr_html_``): the
facts ``ensil info`` prints and the clusters the workbench's legend shows, as a small table.

Written here rather than borrowed from xarray's HTML repr: that one draws a Dataset's variables
and coordinates; ours names members, clusters and their colours. Every text from the data is
escaped (a variable or member name may hold ``<`` or ``&``).
"""

from html import escape as _escape

_STYLE = ("font-family: sans-serif; font-size: 13px; border-collapse: collapse; "
          "text-align: left")
_CELL = "padding: 2px 10px 2px 0; vertical-align: top"


def _number(value):
    return f"{value:g}" if isinstance(value, float) else str(value)


def _table(title, rows):
    body = "".join(f'<tr><th style="{_CELL}">{_escape(name)}</th><td style="{_CELL}">{cell}</td></tr>'
                   for name, cell in rows)
    return (f'<div class="ensil-repr"><strong>{_escape(title)}</strong>'
            f'<table style="{_STYLE}">{body}</table></div>')


def _names(names, shown=6):
    text = ", ".join(_escape(n) for n in names[:shown])
    return text + (f", … ({len(names)} in all)" if len(names) > shown else "")


def ensemble_html(ensemble):
    info = ensemble.info()
    units = f" [{info['units']}]" if info["units"] else ""
    rows = [("variable", _escape(info["variable"] + units)
             + (f" &mdash; {_escape(info['long_name'])}" if info["long_name"] else "")),
            ("members", f"{info['members']} along {_escape(info['member_dim'] or 'members')}: "
                        + _names(info["member_names"]))]
    for axis in reversed(info["axes"]):  # as the values are indexed: vertical first
        span = f"{_number(axis['first'])} to {_number(axis['last'])}"
        rows.append((axis["name"], f"{axis['size']} from {span}"
                     + (f" {_escape(axis['units'])}" if axis["units"] else "")))
    if info["time_steps"]["labels"]:
        labels = info["time_steps"]["labels"]
        rows.append(("time", f"{len(labels)} steps along {_escape(info['time_steps']['dimension'])}"
                             f": {_names(labels, 3)}"))
    if info["grid_mapping"]:
        rows.append(("grid mapping", _escape(str(info["grid_mapping"]))))
    low, high = info["range"]
    rows.append(("values", f"{_number(low)} to {_number(high)}, mean {info['mean']:.4g}"
                           + (f", {info['missing']} missing" if info["missing"] else "")))
    rows.append(("source", _escape(str(ensemble.source))))
    for warning in ensemble.warnings:
        rows.append(("warning", _escape(warning)))
    return _table("ensil.Ensemble", rows)


def _swatch(colour):
    return (f'<span style="display: inline-block; width: 0.9em; height: 0.9em; '
            f'background: {_escape(colour)}; border: 1px solid #444; vertical-align: middle">'
            f'</span>')


def result_html(result):
    members = list(result.members)
    clusters = list(result.clusters)
    colours = list(result.colors)
    cluster_rows = []
    for number in sorted(set(clusters)):
        inside = [m for m, c in zip(members, clusters) if c == number]
        colour = colours[clusters.index(number)]
        cluster_rows.append((f"cluster {number}",
                             f"{_swatch(colour)} {len(inside)} member"
                             f"{'' if len(inside) == 1 else 's'}: {_names(inside)}"))
    median = result.median_member
    outliers = list(result.outliers)
    rows = [("isovalue", _number(float(result.isovalue))),
            ("clusters", f"{result.k} ({_escape(result.linkage_method)} linkage)")]
    rows += cluster_rows
    if median >= 0:
        rows.append(("median member", _escape(members[median])))
    rows.append(("outliers", _names([members[m] for m in outliers]) if outliers else "none"))
    if len(result.members_without_data):
        rows.append(("without data", _names(list(result.members_without_data))))
    rows.append(("built", "from the mesh cache" if result.from_cache
                 else f"in {sum(result.seconds.values()):.2f} s"))
    return _table("ensil.PreprocessResult", rows)
