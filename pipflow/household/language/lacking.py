"""A machine of the home that this home does not have, named as a thing to act on ("switch on the
dishwasher" where there is none): the command cannot be done here, so it is refused as
impossible (a :class:`~pipflow.errors.Refusal` naming what the home lacks), not as words the
reader could not place (docs/household.md, "what the home lacks").

Only the machines and fixtures people have in homes (:data:`MACHINES`), only when the word names
nothing of this home and is no word of the lexicon, only when it is named as a thing (after a
determiner), and only in a clause not set aside as talk ("the dishwasher's broken, so wash the mug"
sets its clause aside first). A negation anywhere keeps the plain refusal: "not the dishwasher"
may say where things should not go, which is no impossibility."""
from __future__ import annotations

from pipflow.errors import Refusal, TranslationError
from pipflow.household.language.lexicon import words_of
from pipflow.language.asides import NEGATION

#: machines of homes that a command may ask to work or to hold things, and that no other thing of
#: a home is called by: "kettle", "oven", "heater", "telly", "radio" are not here, for people call
#: an urn, a range, a stove, a monitor or a stereo so (the home's own words, or the kinds of
#: lexicon ``KIND_WORDS``, say which), and a refusal as impossible of a thing the home has would
#: be a misreading; nor "washer", "dryer", "hoover", "extractor", "blender", which people say for
#: a washing machine, a tumble drier, a vacuum, a cooker hood or a food processor
MACHINES = frozenset({"dishwasher", "dishwashers", "microwave", "toaster", "dehumidifier", "humidifier"})
#: words that name a thing after them
_DETERMINERS = {"the", "my", "our", "your", "a", "an", "that", "this"}
#: words that end a clause
_MARKS = {",", ".", ";", "!", "?", ":"}
#: how a clause opens when it says what is so, or why ("the dishwasher's broken", "because the
#: dryer is full"): a thing named in it is spoken of, not asked of
_STATING = _DETERMINERS | {"it", "its", "i", "im", "we", "he", "she", "they", "there", "theres", "because", "since",
                           "as", "cos", "coz", "cause", "if", "when", "while", "whilst", "though", "although"}


def lacking(command: str, error: TranslationError) -> Refusal | None:
    """The refusal as impossible when the words the reader could not place (``error.unread``)
    include a machine this home lacks named as a thing (module docstring); None otherwise."""
    unread = [w.lower() for w in getattr(error, "unread", [])]
    words = words_of(command)
    if not unread or any(w in NEGATION for w in words):
        return None
    named = [w for k, w in enumerate(words) if w in unread and w in MACHINES and k and words[k - 1] in _DETERMINERS
             and _asked(words, k)]
    if not named:
        return None
    return Refusal(f"this home has no {' or '.join(dict.fromkeys(named))} (in {command.strip()!r}): what is asked "
                   "of it cannot be done here")


def _asked(words: list[str], k: int) -> bool:
    """Whether the thing named at ``k`` is asked of: its clause opens with no subject, determiner
    or subordinator (:data:`_STATING`), as an order does ("switch on the dishwasher", "could you run
    the dishwasher", "heat it in the microwave")."""
    start = k
    while start and words[start - 1] not in _MARKS:
        start -= 1
    return words[start] not in _STATING
