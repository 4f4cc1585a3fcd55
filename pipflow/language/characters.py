"""The characters a command reader reads, and a refusal that quotes every other one.

Why a rule of its own: a reader that skips what it does not know reads the rest as if it were the
whole command. ``shelf2 holds 2³ product1`` was read as "holds 2" (the superscript skipped), and
``3½`` and ``²3`` both as 3, because the word splitter only ever matched ASCII letters and
digits and silently stepped over anything else. A silently changed count is the worst misreading
there is (robots move), so every domain's reader declares its alphabet and refuses the rest
before reading a word.

The principle, for every reader:

* **An alphabet, never a guess.** A reader reads ASCII letters and digits, white space, and a
  fixed list of marks, each with a stated reading (a reader passes its list to :func:`unread`).
  Any other character is refused, with the word it stands in quoted as the user wrote it, the
  character named (Unicode name and code point), and what to write instead.
* **No compatibility folding.** Unicode's compatibility mappings change meaning: NFKC turns
  ``2³`` into ``23`` and ``½`` into ``1⁄2``. Other scripts' digits (Arabic-Indic ``٣``,
  Devanagari ``३``), superscripts, fractions and fullwidth forms (``３``, ``ｓｈｅｌｆ２``) are
  refused like any other character outside the alphabet. For a fullwidth form or an accented
  letter the message shows the ASCII spelling the user probably meant, as a suggestion: the
  reader never reads it so by itself (but see accented talk, below).
* **An accented word is read only as talk.** A word whose only characters outside the alphabet
  are accented Latin letters ("Québec", "là", "Montréal-Nord": a letter and combining accents, by
  Unicode's canonical decomposition; or a letter with a stroke, "ħ", "ł", "ø", which Unicode keeps
  whole) is spelled without its accents when no part of it, spelled
  so, is a word the reader reads (:func:`accents_folded`). It can then only be set aside as talk,
  or be quoted in a refusal; the echo says how it was spelled. A word that would read as one of
  the reader's words ("à" as "a", "café" where a place is called cafe) is refused as before: an
  accent may make it another word, and the reader never guesses which.
* **A world's own spelling is no guess.** A word the world declares with accents for one of its
  things ("açaí" for acai, "câmara 1" for chamber1) is read as that thing
  (:func:`declared_spellings`), before the rule above; another accent on the same word is not
  declared, and stays under it.
* **The Turkish keyboard's i is i** ("ı", "İ": :func:`turkish_i`): on that keyboard they are the
  letter i typed where English types it, not an accent; the word is read with "i". A letter of
  another script drawn like a Latin one (Cyrillic "с" in "сitramon", Greek "ο") is not: it is
  refused as any other character, as the tests of bad inputs hold.
* **Typography the readers already read stays read**: curly apostrophes and quotes, dashes and
  the minus sign, the arrow for "to", the multiplication sign for "x", the ellipsis, and any
  white space (a no-break space is a space). Those are in each reader's list with their reading.

Line breaks: a line break ends a sentence, as a full stop does; a command wrapped in the middle
of a sentence still reads, because :func:`line_readings` offers both readings and the reader
keeps the one that makes sense (refusing when both do and they differ).
"""
from __future__ import annotations

import re
import unicodedata
from typing import Callable

from pipflow.errors import TranslationError

#: ASCII letters and digits: the characters of every word a reader reads
WORD_CHARS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789")
#: words quoted in one refusal at most (the rest are counted)
MAX_QUOTED = 5
#: a line break of any kind (what str.splitlines splits at), with the spaces around it
LINE_BREAK = re.compile(r"[^\S\r\n\v\f\x1c-\x1e\x85\u2028\u2029]*"
                        r"(?:\r\n|[\r\n\v\f\x1c-\x1e\x85\u2028\u2029])\s*")


def unread(text: str, marks: str | frozenset[str]) -> list[tuple[str, str]]:
    """``(word, character)`` for each character of ``text`` outside the alphabet (ASCII letters
    and digits, white space, and ``marks``), in order, once per word: the word is the run of
    non-space characters around it, as the user wrote it."""
    allowed = WORD_CHARS | frozenset(marks)
    out: list[tuple[str, str]] = []
    for m in re.finditer(r"\S+", text):
        word = m.group(0)
        bad = next((ch for ch in word if ch not in allowed), None)
        if bad is not None:
            out.append((word, bad))
    return out


def refuse_unread(text: str, marks: str | frozenset[str], reader: str = "commands") -> None:
    """Raise :class:`TranslationError` quoting every word of ``text`` with a character outside
    the alphabet (module docstring); return silently when there is none."""
    found = unread(text, marks)
    if not found:
        return
    parts = [_describe(word, ch, reader) for word, ch in found[:MAX_QUOTED]]
    more = len(found) - MAX_QUOTED
    tail = f" (and {more} more word{'s' if more > 1 else ''} like it)" if more > 0 else ""
    raise TranslationError("; ".join(parts) + tail)


def _name(ch: str) -> str:
    return f"U+{ord(ch):04X} {unicodedata.name(ch, 'unnamed character')}"


def _describe(word: str, ch: str, reader: str) -> str:
    """What is wrong with one word, and what to write instead."""
    category = unicodedata.category(ch)
    if category[0] == "C" or category in ("Zl", "Zp"):  # control, format (zero-width), private, unassigned
        shown = word.replace(ch, "")
        return (f"an invisible character ({_name(ch)}) in '{shown}' is not read in {reader}; delete it")
    hint = _ascii_spelling(word)
    also = f" (did you mean '{hint}'?)" if hint else ""
    if _numeric(ch):
        return (f"'{word}': '{ch}' ({_name(ch)}) is not one of the digits 0-9 read in {reader}; "
                f"write the number with them{also}")
    if category[0] == "L" or category[0] == "M":
        return (f"'{word}': '{ch}' ({_name(ch)}) is not one of the letters a-z read in {reader}; "
                f"write the word with them{also}")
    return f"'{word}': the symbol '{ch}' ({_name(ch)}) is not read in {reader}; write it in words{also}"


def _numeric(ch: str) -> bool:
    try:
        unicodedata.numeric(ch)
    except (TypeError, ValueError):
        return False
    return True


#: Latin letters with a stroke or a slash, which Unicode does not decompose into a letter and an
#: accent (Maltese "ħ", Polish "ł", Croatian "đ", Danish "ø"): each spelt as its letter without the
#: stroke, as those languages' speakers spell them on a keyboard without it ("habib", "zloty")
_STROKED = {"\u0127": "h", "\u0126": "H", "\u0142": "l", "\u0141": "L", "\u0111": "d", "\u0110": "D",
            "\u00f8": "o", "\u00d8": "O", "\u0167": "t", "\u0166": "T", "\u0180": "b", "\u0268": "i"}


def _ascii_spelling(word: str, widths: bool = True) -> str | None:
    """The ASCII spelling of a word whose only foreign characters are fullwidth or halfwidth
    forms or accented letters (``ｓｈｅｌｆ２`` -> ``shelf2``, ``prodüct1`` -> ``product1``), for a
    suggestion; None when it has none, or when any character would change meaning (superscripts,
    fractions, other scripts' digits: their compatibility forms are not the same character).
    ``widths=False``: accented and stroked Latin letters only ("Québec" -> "Quebec", "ħabib" ->
    "habib"; a fullwidth form, "ß" or a sign with an accent gives None), the spelling
    :func:`accents_folded` may read."""
    out = []
    for ch in word:
        if ch.isascii():
            out.append(ch)
            continue
        decomposition = unicodedata.decomposition(ch)
        if ch in _STROKED:
            base = _STROKED[ch]
        elif widths and decomposition.startswith(("<wide>", "<narrow>")):
            base = unicodedata.normalize("NFKC", ch)
        elif decomposition and not decomposition.startswith("<") and (widths or unicodedata.category(ch)[0] == "L"):
            base = "".join(c for c in unicodedata.normalize("NFD", ch) if not unicodedata.combining(c))  # accents
        else:
            return None
        if not base.isascii() or not (widths or base.isalpha()):
            return None
        out.append(base)
    spelled = "".join(out)
    return spelled if spelled != word else None


def accents_folded(command: str, reads: Callable[[str], bool]) -> tuple[str, list[str]]:
    """The command with each accented word that can only be talk spelled without its accents, and
    a note for each (module docstring). ``reads(word)``: whether the reader reads a lower-case
    word of ASCII letters as one of its own (a world name, a grammar word, a number, or a typo
    of one of them); a word with any such part stays as written, to be refused by
    :func:`refuse_unread`. ``reads`` is asked only when the command has an accented word."""
    notes: list[str] = []

    def fold(m: re.Match) -> str:
        word = m.group(0)
        plain = _ascii_spelling(word, widths=False)
        if plain is None or any(reads(part) for part in re.findall(r"[a-z]+", plain.lower())):
            return word
        notes.append(f"'{word}' read as '{plain}' (spelled without its accents; no word this reader reads, "
                     f"so it can only be talk)")
        return plain
    if command.isascii():
        return command, []
    return re.sub(r"\S+", fold, command), notes


#: the letters of a Turkish keyboard that stand for the English "i" and "I": its dotless "ı" and
#: dotted capital "İ" are Turkish's own case pair of i, typed where an English keyboard types i / I
_TURKISH_I = {"\u0131": "i", "\u0130": "I"}


def turkish_i(command: str) -> tuple[str, list[str]]:
    """The command with the Turkish keyboard's "ı" and "İ" read as "i" and "I" ("dıspatch",
    "fıve", "İnbound": dispatch, five, Inbound), and a note for each word so read. Not an accent
    taken off: on that keyboard they are the letter i itself (Turkish pairs "ı" with "I" and "i"
    with "İ"), so the word has one reading. Run after :func:`declared_spellings` (a world may
    declare a word with them), before :func:`accents_folded` ("Günaydın" then folds as talk)."""
    if command.isascii() or not any(ch in command for ch in _TURKISH_I):
        return command, []
    notes: list[str] = []

    def read(m: re.Match) -> str:
        word = m.group(0)
        plain = "".join(_TURKISH_I.get(ch, ch) for ch in word)
        if plain != word:
            notes.append(f"'{word}' read as '{plain}' (the Turkish keyboard's i)")
        return plain
    return re.sub(r"\S+", read, command), notes


def digit_words(world: dict, kinds: tuple[str, ...]) -> dict[str, str]:
    """The words a world declares for its things with a digit among their letters ("fa7m",
    "man2ouche": Arabic typed in Latin letters), lower case, -> the thing's name: what
    :func:`declared_spellings` reads, before any digit of them could be taken for a count."""
    return {word.lower(): str(name) for kind in kinds for name, entry in (world.get(kind) or {}).items()
            for word in ((entry.get("words") or []) if isinstance(entry, dict) else [])
            if isinstance(word, str) and word.isascii() and re.search(r"[A-Za-z]\d|\d[A-Za-z]", word)}


def non_ascii_words(world: dict, kinds: tuple[str, ...]) -> dict[str, str]:
    """The words a world declares for its things with letters outside the alphabet ("açaí" for
    acai, "câmara 1" for chamber1), lower case and composed (NFC), -> the thing's name: what
    :func:`declared_spellings` reads. ``kinds``: the world's sections of named things. A word of
    such a spelling that the world also writes without its accents, as a name or in another word
    ("sofía" in "bed of sofía" beside "bed of sofia"; "sartén" for sarten), is declared on its own
    -> that spelling: the world says the two are one word, so "the room of Sofía" reads as well."""
    out: dict[str, str] = {}
    plain: set[str] = set()   # the words of the world's names and words spelled in the alphabet
    for kind in kinds:
        for name, entry in (world.get(kind) or {}).items():
            plain.add(str(name).lower())
            for word in (entry.get("words") or []) if isinstance(entry, dict) else []:
                if isinstance(word, str) and not word.isascii():
                    out[unicodedata.normalize("NFC", word).lower()] = str(name)
                elif isinstance(word, str):
                    plain.update(word.lower().split())
    for spelled in list(out):
        # a word the world spells both ways ("bed of sofía", "bed of sofia"): that accent is its own
        for part in spelled.split():
            folded = _ascii_spelling(part, widths=False)
            if folded is not None and folded != part and folded in plain:
                out.setdefault(part, folded)
    return out


def declared_spellings(command: str, declared: dict[str, str]) -> tuple[str, list[str]]:
    """The command with each spelling the world itself declares with letters outside the alphabet
    (:func:`non_ascii_words`), or with digits among its letters (:func:`digit_words`: "fa7m"),
    written as the name it declares it for, and a note for each. The world's own spelling is no
    guess, so the accent rule of this module (an accented word is read only as talk) and the
    refusal of a number written into a word do not bear on it; every other such word stays under
    those rules. The command is composed first (NFC: canonical, so no character changes meaning),
    so an accent typed as a combining mark matches too."""
    if not declared or (command.isascii() and not any(ch.isdigit() for w in declared for ch in w)):
        return command, []
    notes: list[str] = []
    text = unicodedata.normalize("NFC", command)
    for spelled in sorted(declared, key=len, reverse=True):
        def name(m: re.Match, spelled: str = spelled) -> str:
            said = declared[spelled] + m.group(0)[len(spelled):]
            notes.append(f"'{m.group(0)}' read as {said} (a spelling this world declares)")
            return said
        plural = "(?:e?s)?" if " " not in spelled else ""   # "almojábanas": the declared word's plural
        text = re.sub(r"(?<!\w)" + re.escape(spelled) + plural + r"(?!\w)", name, text, flags=re.IGNORECASE)
    return text, notes


#: pictographs that say how the writer feels and nothing else: faces, hands and gestures, hearts
#: (ranges of code points; a food, a number in a box, an arrow or a tick is none: those could say
#: what to move or how many, and stay refused as symbols)
_EXPRESSION_RANGES = ((0x1F600, 0x1F64F),   # emoticons: faces and gestures ("🙄", "🙏")
                      (0x1F910, 0x1F92F),   # supplemental faces and hands ("🤦", "🤞")
                      (0x1F930, 0x1F93A),   # people gesturing ("🤷")
                      (0x1F970, 0x1F97A),   # faces ("🥲", "🥵")
                      (0x1F9D0, 0x1F9D0),   # face with monocle
                      (0x1F44A, 0x1F450),   # hands ("👍", "👌", "👏")
                      (0x1F4AA, 0x1F4AA),   # flexed biceps
                      (0x1F590, 0x1F596),   # raised hands
                      (0x1F493, 0x1F49F),   # hearts
                      (0x2763, 0x2764),     # heart marks
                      (0x1F389, 0x1F38A),   # party popper, confetti ball ("🎉": joy)
                      (0x2728, 0x2728),     # sparkles
                      (0x2639, 0x263A))     # frowning and smiling face
#: what may follow such a pictograph within it: skin tones, the joiner, a variation selector, and
#: the gender signs that a joiner adds ("🤦‍♂️")
_EXPRESSION_PARTS = "\U0001F3FB-\U0001F3FF\u200d\ufe0f\u2640\u2642"
#: Korean chat's laughter and tears, typed as repeated jamo ("ㅋㅋ", "ㅎㅎ", "ㅠㅠ", "ㅜㅜ"): a run of
#: two or more; one jamo alone may be a typo of a word, and stays refused
_JAMO_FEELINGS = "\u314b\u314e\u315c\u3160"
#: faces typed in ASCII (":)", ":-(", ";)", ":D", ":P", ":'(", "^^", "^_^", "T_T", ">_<", "xD"), each
#: a word of its own (white space or a mark of a sentence's end around it): "10:30" and "(see 8)"
#: are none, and "<3" is left to the refusal of "<" (it may say less than 3)
_ASCII_FACES = r"(?<!\S)(?:[:;=]'?-?[()DPpOo/|]+|\^[_-]?\^|T[_.]T|>_<|[xX]D+)(?=\s|[.,!?]|$)"
_EXPRESSION = re.compile("(?:[" + "".join(f"{chr(a)}-{chr(b)}" for a, b in _EXPRESSION_RANGES)
                         + "][" + _EXPRESSION_PARTS + "]*)+"
                         + f"|[{_JAMO_FEELINGS}]{{2,}}|" + _ASCII_FACES)
#: a tilde that draws out the word it closes ("Thank you~", "please~~"), as East Asian chat types
#: a friendly tone: only after a letter and before a space, a mark or the end; "2~3" (a range) and
#: a tilde before a word stay refused
_DRAWN_OUT = re.compile(r"(?<=[A-Za-z])~+(?=[\s.,!?;:]|$)")


def without_expressions(command: str) -> tuple[str, list[str]]:
    """The command with its pictographs of feeling (faces, hands, hearts: :data:`_EXPRESSION_RANGES`;
    Korean jamo of laughter and tears, "ㅋㅋ", "ㅠㅠ"; faces typed in ASCII, ":)") read as the end of a sentence, a tilde drawing
    out a word ("you~") left out, and those marks, to be said as set aside. People end a
    message or a sentence with one ("dispatch is short again 🙄 send 4 more"); it holds no count,
    name or word of an order. Every other character outside the alphabet is still refused
    (:func:`refuse_unread`)."""
    found = _EXPRESSION.findall(command) + _DRAWN_OUT.findall(command)
    if not found:
        return command, []
    return _DRAWN_OUT.sub("", _EXPRESSION.sub(" . ", command)), found


def line_readings(command: str) -> list[str]:
    """The readings of a command's line breaks: ``[command]`` when no line break is inside it;
    otherwise the command with each break read as the end of a sentence (first) and, as a second
    reading, each break read as a space (a sentence wrapped onto the next line). A break after a
    sentence's own full stop (or ; ! ?) reads the same both ways: then there is one reading."""
    text = command.strip()
    if not LINE_BREAK.search(text):
        return [command]

    def ended(m: re.Match) -> str:
        return " " if text[:m.start()].rstrip()[-1:] in (".", ";", "!", "?", "\u2026") else ". "

    broken, joined = LINE_BREAK.sub(ended, text), LINE_BREAK.sub(" ", text)
    return [broken] if broken == joined else [broken, joined]
