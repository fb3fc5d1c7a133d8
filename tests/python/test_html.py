"""What an Ensemble and a PreprocessResult show in Jupyter (_repr_html_): well-formed HTML
with the facts ``ensil info`` gives, each cluster with the colour the workbench draws it in,
and every text from the data escaped."""

from html.parser import HTMLParser

import numpy as np

import ensil

VOID = {"br", "hr", "img", "meta", "col"}


class _Tags(HTMLParser):
    """Checks that every element is closed in order, and gathers the text and the styles."""

    def __init__(self):
        super().__init__()
        self.open = []
        self.text = []
        self.styles = []

    def handle_starttag(self, tag, attrs):
        self.styles += [value for name, value in attrs if name == "style"]
        if tag not in VOID:
            self.open.append(tag)

    def handle_endtag(self, tag):
        assert self.open and self.open[-1] == tag, f"</{tag}> closes {self.open}"
        self.open.pop()

    def handle_data(self, data):
        self.text.append(data)


def _parsed(html):
    tags = _Tags()
    tags.feed(html)
    tags.close()
    assert tags.open == [], f"unclosed: {tags.open}"
    return " ".join(tags.text), tags.styles


def test_an_ensemble_shows_what_ensil_info_says():
    demo = ensil.demo(members=4)
    text, _ = _parsed(demo._repr_html_())
    info = demo.info()
    assert "wind_speed [m s-1]" in text
    assert "4 along number" in text
    for axis in info["axes"]:
        assert f"{axis['name']}" in text and f"{axis['size']} from" in text
    assert "member 1" in text and "member 4" in text


def test_a_result_shows_each_cluster_in_its_colour():
    result = ensil.demo(members=6).preprocess(iso=30, clusters=3, cache=False)
    text, styles = _parsed(result._repr_html_())
    clusters = list(result.clusters)
    for number in set(clusters):
        inside = clusters.count(number)
        assert f"cluster {number}" in text
        assert f"{inside} member" in text
        colour = result.colors[clusters.index(number)]
        assert any(f"background: {colour}" in s for s in styles), colour
    assert result.members[result.median_member] in text


def test_names_from_the_data_are_escaped():
    values = np.random.default_rng(1).random((3, 4, 5, 6), dtype=np.float32)
    axes = {"z": np.arange(4.0), "y": np.arange(5.0), "x": np.arange(6.0)}
    ens = ensil.from_numpy(values, axes=axes, names=["a<b", "c&d", "e"], variable="x<script>")
    html = ens._repr_html_()
    assert "<script>" not in html
    text, _ = _parsed(html)
    assert "x<script>" in text  # shown as written, once unescaped
    assert "a<b" in text and "c&d" in text
