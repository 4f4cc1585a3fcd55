"""Place names on floor drawings can be read: none runs over another or off the floor, and a
place too small for its name has it beside it (pipflow.placelabels, used by the replay and the
matplotlib maps)."""
from __future__ import annotations

import itertools
import re
import tempfile

import pytest

import pipflow
from pipflow.placelabels import GLYPH, place_labels
from pipflow.records.report import write_report

FLOOR = (10.0, 8.0)
#: a household-like floor: a bed, a narrow bookshelf, a wall strip, and two tiny things side by
#: side near the top edge (a light switch beside a floor lamp: the names that used to collide)
PLACES = [("bed", (8.0, 5.0, 1.8, 2.2)), ("bookshelf", (9.6, 0.2, 0.3, 1.4)), ("wall", (5.0, 2.0, 0.1, 4.6)),
          ("lightswitch", (5.0, 7.8, 0.2, 0.1)), ("floorlamp", (5.6, 7.5, 0.3, 0.3)),
          ("garbagecan", (4.2, 0.2, 0.4, 0.4)), ("microwave", (0.2, 2.5, 0.7, 0.6))]


def _extent(name: str, label) -> tuple[float, float, float, float]:
    long, short = GLYPH * label.size * len(name), label.size
    w, h = (short, long) if label.upright else (long, short)
    return label.x - w / 2, label.y - h / 2, w, h


def _shared(a, b) -> float:
    dx = min(a[0] + a[2], b[0] + b[2]) - max(a[0], b[0])
    dy = min(a[1] + a[3], b[1] + b[3]) - max(a[1], b[1])
    return dx * dy if dx > 0 and dy > 0 else 0.0


def test_a_roomy_place_has_its_name_inside_at_full_size() -> None:
    [label] = place_labels([("bed", (1.0, 1.0, 2.0, 2.0))], FLOOR)
    assert label.inside and not label.upright and label.size == pytest.approx(0.42)
    assert (label.x, label.y) == pytest.approx((2.0, 2.0))


def test_a_tall_narrow_place_reads_its_name_upright() -> None:
    [label] = place_labels([("bookshelf", (9.6, 0.2, 0.3, 1.4))], FLOOR)
    assert label.inside and label.upright


def test_no_name_overlaps_another_or_a_place_it_does_not_name_and_all_stay_on_the_floor() -> None:
    labels = place_labels(PLACES, FLOOR)
    boxes = {name: box for name, box in PLACES}
    extents = {name: _extent(name, label) for (name, _), label in zip(PLACES, labels)}
    for (a, ea), (b, eb) in itertools.combinations(extents.items(), 2):
        assert _shared(ea, eb) == 0, (a, b)
    for (name, _), label in zip(PLACES, labels):
        x, y, w, h = extents[name]
        assert -1e-9 <= x and x + w <= FLOOR[0] + 1e-9 and -1e-9 <= y and y + h <= FLOOR[1] + 1e-9, name
        if not label.inside:
            assert all(_shared(extents[name], box) == 0 for other, box in boxes.items() if other != name), name
    beside = {name for (name, _), label in zip(PLACES, labels) if not label.inside}
    assert {"lightswitch", "floorlamp", "garbagecan", "wall"} <= beside


def test_the_household_replay_writes_small_places_names_beside_them_in_dark_ink() -> None:
    run = pipflow.run("household", runs_dir=tempfile.mkdtemp(), cache=False)
    page = write_report(run.record).read_text(encoding="utf-8")
    svg = page[page.index("<svg id='replay-svg'"):page.index("</svg>", page.index("<svg id='replay-svg'"))]
    beside = re.findall(r"class='place-beside'[^>]*>([^<]+)</text>", svg)
    inside = re.findall(r"class='place'[^>]*>([^<]+)</text>", svg)
    assert "lightswitch" in beside and "bed" in inside
    assert "#replay-svg text.place-beside{fill:#3b2a1c" in page
