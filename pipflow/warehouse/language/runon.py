"""Commands said without stops, as a speech recogniser writes what was dictated into a headset or
a phone types a message sent between jobs: "clear out overflow mezzanine should end up with twelve
reams", "forklifts only on this one move ten reams from bulk to dock".

Where a sentence does not read, the word no rule places may open a sentence of its own: the
command is read again with a stop before it, or before one of the words in front of it (the
sentence said before the stop must read by itself), and again where the rest still does not read,
up to :data:`MAX_STOPS` stops. A part a stop makes that is talk by what it is ("thats all for now",
"cheers mate": :meth:`Lexicon.talk`) is set aside, and said. Every word of every other
part is placed, as in any sentence. The readings found are compared: one meaning is the reading
(echoed with its stops); readings that ask for different things are refused with each offered,
and nothing is guessed."""
from __future__ import annotations

from pipflow.errors import PipflowError, TranslationError
from pipflow.warehouse.language.command import lexed_command, parse_reading
from pipflow.warehouse.language.forest import sentence_edges
from pipflow.warehouse.language.lexicon import Lexicon
from pipflow.warehouse.language.readings import meaning_of

#: words that join what comes after them to what came before: no stop after them ("put 2 more on
#: P and / 1 on Q" would read the 1 without the "more" it shares)
JOINING = frozenset({"and", "or", "but", "then", "so", "nor", "plus", "than", "as", "with", ","})
#: words that go on the sentence before them, never open one: where a move goes ("move 2 X from P
#: / to Q" would read a move to anywhere), and "of"
GOING_ON = frozenset({"to", "into", "onto", "of"})
#: the most stops put into one command
MAX_STOPS = 3
#: the most readings tried: each is a parse of the whole command, paid only by a command refused
RUN_ON_PARSES = 24
#: how many words before the one that does not fit a stop is tried
RUN_ON_REACH = 8


def with_stops(command: str, world: dict, error: TranslationError) -> dict | None:
    """The order of ``command`` read with stops where it was said without (see the module), with
    ``read_as`` (the sentences it was read as); None where no such reading reads every word.
    Raises :class:`RunOnChoice` where two such readings ask for different things."""
    found: list[tuple[frozenset[int], dict]] = []
    left = [RUN_ON_PARSES]
    lex = lexed_command(command, world)[0]

    def search(stops: frozenset[int], err: TranslationError) -> None:
        span = getattr(err, "span", None)
        if span is None or len(stops) >= MAX_STOPS or not getattr(err, "unread", False):
            return   # only words no rule reads: a sentence read and refused for its meaning stays refused
        start, end = span
        at = getattr(err, "at", None)
        last = at if at is not None else end - 1
        for stop in range(last, max(start, last - RUN_ON_REACH), -1):
            if left[0] <= 0:
                return
            if not _may_stop(lex, start, stop, end):
                continue
            left[0] -= 1
            tried = stops | {stop}
            try:
                order = parse_reading(command, world, {"*": {"stops": tried}})
            except TranslationError as again:
                # the words before the stop read: the rest may hold another stop
                if (getattr(again, "span", None) or (0, 0))[0] >= stop:
                    search(tried, again)
                continue
            except PipflowError:
                continue
            found.append((tried, order))

    search(frozenset(), error)
    meanings: dict[str, tuple[frozenset[int], dict]] = {}
    for stops, order in found:
        meaning = meaning_of(order, world)
        if meaning is not None:
            meanings.setdefault(meaning, (stops, order))
    if not meanings:
        return None
    readings = [_read_as(command, world, stops, order) for stops, order in meanings.values()]
    if len(readings) > 1:
        raise RunOnChoice(readings, [stops for stops, _ in meanings.values()])
    return readings[0]


def _may_stop(lex: Lexicon, start: int, stop: int, end: int) -> bool:
    """Whether a stop may stand before the recognised token at ``stop`` of the sentence
    ``start:end``: the word before it may end a sentence and the word after it open one, or is
    no word of the grammar, or the rest asks for nothing (talk, set aside), as the grammar says
    (:func:`forest.sentence_edges`). A filter only: every stop is still read."""
    opens, ends = sentence_edges()
    kinds = [(term or ("", None))[0] for term in map(lex.terminal, lex.tokens[start:end])]
    before = [k for k in kinds[:stop - start] if k]
    after = [k for k in kinds[stop - start:] if k]
    joined = str(lex.tokens[stop - 1].value) in JOINING
    # never before a count or a word that attaches to what came before ("... 3 more X / 5", "... on
    # P / 1 on Q", "move 2 X from P / to Q 5"): a bare count, or a part that shares the words before
    # it, would be read as a sentence of its own
    attached = next((str(t.value) for t in lex.tokens[stop:end] if lex.terminal(t) is not None), "") in GOING_ON
    return bool(before and after) and not joined and not attached and after[0] != "NUM" and before[-1] in ends and (
        after[0] in opens or after[0] == "UNKNOWN" or lex.talk(lex.tokens[stop:end]))


def _read_as(command: str, world: dict, stops: frozenset[int], order: dict) -> dict:
    """The order with the sentences the command was read as, for the echo (fillers before a stop
    are said with the sentence after it: "... on vat west / please thats all")."""
    lex = lexed_command(command, world, stops)[0]
    cuts = [0]
    for stop in sorted(stops):
        while stop - 1 > cuts[-1] and lex.terminal(lex.tokens[stop - 1]) is None:
            stop -= 1
        cuts.append(stop)
    cuts.append(len(lex.tokens))
    said = [" ".join(t.text for t in lex.tokens[a:b]).replace(" zzposs", "'s").strip(" ,:")
            for a, b in zip(cuts, cuts[1:])]
    return {**order, "read_as": [p for p in said if p]}


class RunOnChoice(TranslationError):
    """A command said without stops that reads with stops put in more than one way, asking for
    different things: each is offered (the candidates read it with each set of ``stops``), none
    is acted on."""

    def __init__(self, orders: list[dict], stops: list[frozenset[int]]):
        super().__init__("said without stops, it reads in more than one way, each asking for something else: "
                         + "; or ".join(" / ".join(f"'{p}'" for p in o["read_as"]) for o in orders)
                         + ": nothing is guessed; end each sentence with a full stop")
        self.stops = stops
