"""A tannery's store, a world no benchmark uses, for the reader tests of issue 23's fifth round:
two vats that share a word ("the vat" names neither), a place said short ("dry loft"), products
whose head nouns are verbs of the grammar ("cart wheel": "wheels"; "belt round": "rounds"), robots
named by a shared stem and by kind."""
from __future__ import annotations

TANNERY = {
    "name": "tannery",
    "floor": {"width": 30, "height": 20},
    "shelves": {
        "drying_loft": {"x": 2, "y": 14, "width": 4, "depth": 2, "capacity": 14, "access": [4, 13]},
        "vat_east": {"x": 10, "y": 14, "width": 4, "depth": 2, "capacity": 12, "access": [12, 13]},
        "vat_west": {"x": 20, "y": 14, "width": 6, "depth": 2, "capacity": 12, "access": [23, 13]},
        "finishing_table": {"x": 4, "y": 3, "width": 6, "depth": 2, "capacity": 10, "access": [7, 6]},
    },
    "products": {"cart_wheel": {"color": "brown"}, "belt_round": {"color": "black"}, "dye_drum": {"color": "blue"}},
    "stock": {"drying_loft": {"cart_wheel": 6, "belt_round": 2}, "vat_east": {"cart_wheel": 1, "dye_drum": 4},
              "vat_west": {"belt_round": 5}, "finishing_table": {"dye_drum": 1}},
    "robots": {
        "mule1": {"start": [1, 8], "skills": {"carry": 2}},
        "mule2": {"start": [5, 8], "skills": {"carry": 2}},
        "crane": {"kind": "gantry", "start": [15, 8], "skills": {"carry": 4}},
        "flea": {"kind": "amr", "start": [18, 8], "skills": {"carry": 1}},
    },
}
