#!/usr/bin/env python3
"""Build the grounding lexicon (crates/shenlong/src/ground/lexicon.txt).

Inputs:
  * WordNet 3.0's noun database (data.noun, index.noun, noun.exc), as installed by
    Debian's package wordnet-base under /usr/share/wordnet;
  * tools/lexicon/categories.txt: the seed terms, each with its chosen WordNet sense;
  * tools/lexicon/extra.txt: hand-written synonyms and hypernyms that WordNet lacks.

The output format and the hygiene rules are described in tools/lexicon/README.md.
Pure standard library; deterministic (running it twice gives the same bytes).

Usage: python3 tools/lexicon/build_lexicon.py [--wordnet DIR] [--out FILE]
"""

from __future__ import annotations

import argparse
import glob
import hashlib
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
DEFAULT_WORDNET = "/usr/share/wordnet"
DEFAULT_OUT = os.path.join(REPO, "crates", "shenlong", "src", "ground", "lexicon.txt")
DEFAULT_CATEGORIES = os.path.join(HERE, "categories.txt")
DEFAULT_EXTRA = os.path.join(HERE, "extra.txt")
DEFAULT_EXAMPLES = os.path.join(REPO, "examples")
WORDNET_FILES = ("data.noun", "index.noun", "noun.exc")

# The command recorded in the output's header (fixed text, so that the output does
# not depend on the directory the script was started from).
COMMAND = "python3 tools/lexicon/build_lexicon.py"

# WordNet lemmas that are never taken as synonyms, whatever synset they come from:
# lemma -> reason. extra.txt can still give one of them to a concept explicitly.
# Some of them would also be dropped by the collision rule today; they are listed so
# that they stay out if the seed list changes. The list is kept small: an entry is
# added only for a lemma of a chosen synset that would mislead on its own.
BLOCKED_SYNONYMS = {
    # vulgar or slang senses of the toilet
    "crapper": "vulgar slang for toilet",
    "john": "slang for toilet; also a first name",
    "throne": "slang for toilet; a throne is a chair",
    "potty": "a potty is a child's chamber pot, not the toilet",
    "commode": "also a chest of drawers or a chair with a chamber pot",
    "can": "slang for toilet; a can is a tin can",
    "head": "slang for toilet; also the body part",
    "lavatory": "British for the toilet room; in WordNet also a washbasin",
    # words that name a different, common object in a room
    "box": "slang for television; a box is a box",
    "set": "for a television or radio; a set is many things",
    "receiver": "for a television; a receiver is also a telephone handset or an amplifier",
    "stand": "a stand is any support (tv stand, iv stand, mayo stand)",
    "light": "a light is any source of light, not one kind",
    "plant": "a plant is any plant; also a factory",
    "table": "a table is a table, not the thing WordNet groups with it",
    "board": "cutting board, whiteboard, ironing board, plank: too many boards",
    "press": "for a wardrobe; a press is also a drill press or a printing press",
    "file": "for a filing cabinet; a file is also a document or a rasp",
    "paper": "for a newspaper; paper is also sheets of paper, toilet paper, paper towel",
    "material": "for cloth; anything is material",
    "plastic": "for a credit card; anything can be plastic",
    "wear": "for clothing; too general and mostly a verb",
    "text": "for a textbook; text is written words",
    "grip": "for a suitcase; a grip is also a handle",
    "go-cart": "a go-cart (go-kart) is a small racing car, not a cart",
    "puff": "for an ottoman or a quilt; a puff is also a powder puff",
    "voider": "obsolete word for a laundry basket",
    "pendant": "for a chandelier; a pendant is mostly a necklace",
    "pendent": "for a chandelier; archaic spelling of pendant",
    "ticker": "slang for a watch; also the heart or a stock ticker",
    "murphy": "slang for a potato; a Murphy bed is a bed",
    "exposure": "for a photograph; exposure is mostly not an object",
    "washstand": "a washstand is a piece of furniture that holds a basin",
    "threshold": "the threshold is the sill under a door, not the doorway",
    "room access": "for a doorway; not how people name it",
    "chest": "for a chest of drawers; a chest is also a lidded box",
    "bureau": "in British English a bureau is a writing desk",
    "chamber": "for a bedroom; a chamber is any room",
    "sleeping accommodation": "for a bedroom; not how people name the room",
    "shop": "for a workshop; a shop is mostly a store",
    "surgery": "for an operating room; in British English a doctor's office",
    "mantle": "for a curtain; a mantle is a cloak or a mantelpiece",
    "pall": "for a curtain; a pall is a coffin cloth",
    "cover": "for a blanket; a cover is any cover",
    "spread": "for a bedspread; too general",
    "wheel": "for a bicycle; a wheel is a wheel",
    "cycle": "for a bicycle; too general",
    "tape": "for a tape measure; tape is sticky tape",
    "rule": "for a ruler; a rule is not an object",
    "prize": "for a trophy; a prize is anything awarded",
    "notice": "for a poster; not an object",
    "bill": "for a poster; a bill is an invoice or a banknote",
    "card": "for a poster; a card is a card",
    "posting": "for a poster; not an object",
    "lid": "slang for hat; a lid is a lid",
    "bath": "a bath is a bathtub (British) and a bathroom; decided in extra.txt",
    "convertible": "for a sofa bed; a convertible is mostly a car",
    "comfort": "for a quilt; not an object",
    "tuner": "for a radio; a tuner is a component",
    "wireless": "for a radio; now means wi-fi",
    "asphyxiator": "obscure",
    "dolly": "for a doll; a dolly is also a hand truck",
    "lumber": "for a baseball bat; lumber is timber",
    "cell": "for a cell phone; a cell is also a battery or a prison cell",
    "instrument": "for a musical instrument; also a medical or measuring instrument",
    "marine museum": "for an aquarium; a building, not the fish tank",
    "swab": "for a mop; a swab is mostly a cotton swab",
    "swob": "for a mop; variant of swab",
    "alarm": "for an alarm clock; an alarm is also a smoke or burglar alarm",
    "warmer": "for a heater; a warmer is also a plate or bottle warmer",
    "lounger": "for a recliner; a (sun) lounger is a garden chair",
    "wall plug": "for an outlet; a wall plug is also a plastic anchor for a screw",
    "electric light": "for a light bulb; any electric lamp is an electric light",
    "flora": "for a plant; the plants of a region, not one plant",
    "plant life": "for a plant; plants collectively, not one plant",
    "staff of life": "for bread; an idiom",
    "wearable": "for clothing; now mostly a fitness tracker or smartwatch",
}

# Hypernym links that WordNet gives but a person would not use when naming the
# object: (term, hypernym) -> reason.
BLOCKED_HYPERNYMS = {
    ("kettle", "pot"): "WordNet's kettle is a stewing pot; nobody calls a tea kettle 'the pot'",
    ("spoon", "container"): "WordNet files a spoon under containers; nobody calls it one",
    ("ladle", "container"): "WordNet files a ladle under vessels; nobody calls it a container",
    ("vase", "jar"): "WordNet files a vase under jars; 'the jar' should not pick a vase",
    ("bathtub", "container"): "WordNet files a bathtub under vessels; nobody calls it a container",
    ("bicycle", "container"): "WordNet files wheeled vehicles under containers",
    ("towel", "cloth"): "'the cloth' should not pick a towel (or a paper towel, which is below towel)",
    ("locker", "room"): "WordNet files a locker under compartment < room; it is furniture",
}

# Irregular plurals of noun.exc that belong to another sense of the word than the one
# the lexicon uses: (plural, singular) -> reason. Also applies to multi-word phrases
# ending in the singular.
BLOCKED_PLURALS = {
    ("vacua", "vacuum"): "the plural of 'vacuum' (a vacuum cleaner) is 'vacuums'",
    ("camerae", "camera"): "Latin plural for chambers; the plural of a camera is 'cameras'",
}

# ProcTHOR's object types, as the lower-case words people read them: each must
# resolve to a concept of the lexicon (as a term, a synonym, or a regular plural).
PROCTHOR_TYPES = {
    "AlarmClock": "alarm clock", "AluminumFoil": "aluminum foil", "Apple": "apple",
    "ArmChair": "armchair", "BaseballBat": "baseball bat", "BasketBall": "basketball",
    "Bed": "bed", "Blinds": "blinds", "Book": "book", "Boots": "boots", "Bottle": "bottle",
    "Bowl": "bowl", "Box": "box", "Bread": "bread", "ButterKnife": "butter knife",
    "CD": "cd", "Candle": "candle", "Cart": "cart", "CellPhone": "cell phone",
    "Chair": "chair", "Cloth": "cloth", "ClothesDryer": "clothes dryer",
    "CoffeeMachine": "coffee machine", "CoffeeTable": "coffee table",
    "CounterTop": "countertop", "CreditCard": "credit card", "Cup": "cup", "Desk": "desk",
    "DeskLamp": "desk lamp", "Desktop": "desktop", "DiningTable": "dining table",
    "DishSponge": "dish sponge", "DogBed": "dog bed", "Doorframe": "doorframe",
    "Doorway": "doorway", "Dresser": "dresser", "Dumbbell": "dumbbell", "Egg": "egg",
    "Faucet": "faucet", "FloorLamp": "floor lamp", "Footstool": "footstool", "Fork": "fork",
    "Fridge": "fridge", "GarbageBag": "garbage bag", "GarbageCan": "garbage can",
    "HandTowel": "hand towel", "HandTowelHolder": "hand towel holder",
    "HousePlant": "houseplant", "Kettle": "kettle", "KeyChain": "key chain",
    "Knife": "knife", "Ladle": "ladle", "Laptop": "laptop",
    "LaundryHamper": "laundry hamper", "Lettuce": "lettuce", "LightSwitch": "light switch",
    "Microwave": "microwave", "Mug": "mug", "Newspaper": "newspaper", "Ottoman": "ottoman",
    "Painting": "painting", "Pan": "pan", "PaperTowelRoll": "paper towel roll", "Pen": "pen",
    "Pencil": "pencil", "PepperShaker": "pepper shaker", "Pillow": "pillow", "Plate": "plate",
    "Plunger": "plunger", "Pot": "pot", "Potato": "potato", "RemoteControl": "remote control",
    "RoomDecor": "room decor", "Safe": "safe", "SaltShaker": "salt shaker",
    "ScrubBrush": "scrub brush", "ShelvingUnit": "shelving unit",
    "ShowerCurtain": "shower curtain", "ShowerHead": "shower head", "SideTable": "side table",
    "Sink": "sink", "SoapBar": "soap bar", "SoapBottle": "soap bottle", "Sofa": "sofa",
    "Spatula": "spatula", "Spoon": "spoon", "SprayBottle": "spray bottle", "Statue": "statue",
    "Stool": "stool", "TVStand": "tv stand", "TableTopDecor": "tabletop decor",
    "TeddyBear": "teddy bear", "Television": "television", "TennisRacket": "tennis racket",
    "TissueBox": "tissue box", "Toaster": "toaster", "Toilet": "toilet",
    "ToiletPaper": "toilet paper", "ToiletPaperHanger": "toilet paper hanger",
    "Tomato": "tomato", "Towel": "towel", "TowelHolder": "towel holder",
    "VacuumCleaner": "vacuum cleaner", "Vase": "vase", "WashingMachine": "washing machine",
    "Watch": "watch", "WateringCan": "watering can", "Window": "window",
    "WineBottle": "wine bottle",
}
PROCTHOR_ROOMS = {"Kitchen": "kitchen", "LivingRoom": "living room", "Bedroom": "bedroom",
                  "Bathroom": "bathroom"}

TERM_RE = re.compile(r"^[a-z0-9]+(?:[-'.][a-z0-9]+)*\.?(?: [a-z0-9]+(?:[-'.][a-z0-9]+)*\.?)*$")
SENSE_RE = re.compile(r"^(?P<lemma>\S+)\.n\.(?P<num>\d{2,})$")
MARKER_RE = re.compile(r"\((?:a|p|ip)\)$")


class InputError(Exception):
    """A problem with an input file: reported as one line, exit status 2."""


def note(msg: str) -> None:
    print(f"build_lexicon: {msg}", file=sys.stderr)


# ---------------------------------------------------------------- WordNet

class WordNet:
    """The parts of WordNet 3.0's noun database that the lexicon needs."""

    def __init__(self, directory: str):
        paths = {name: os.path.join(directory, name) for name in WORDNET_FILES}
        for name, path in paths.items():
            if not os.path.isfile(path):
                raise InputError(
                    f"WordNet file not found: {path} (install Debian's wordnet-base with "
                    f"'apt-get install wordnet-base', or pass --wordnet DIR)")
        self.paths = paths
        self.index: dict[str, list[str]] = {}  # lemma -> synset offsets, in sense order
        self.synsets: dict[str, tuple[list[str], list[str], str]] = {}  # offset -> (words, hypernym offsets, gloss)
        self.exceptions: list[tuple[str, list[str]]] = []  # (plural, [singular, ...])
        self._read_index(paths["index.noun"])
        self._read_data(paths["data.noun"])
        self._read_exceptions(paths["noun.exc"])

    def digest(self) -> str:
        h = hashlib.sha256()
        for name in WORDNET_FILES:
            with open(self.paths[name], "rb") as f:
                h.update(f.read())
        return h.hexdigest()[:16]

    def _read_index(self, path: str) -> None:
        # lemma pos synset_cnt p_cnt [ptr_symbol...] sense_cnt tagsense_cnt synset_offset...
        with open(path, encoding="utf-8") as f:
            for n, line in enumerate(f, 1):
                if line.startswith("  ") or not line.strip():
                    continue  # licence header
                fields = line.split()
                try:
                    synset_cnt = int(fields[2])
                    p_cnt = int(fields[3])
                    offsets = fields[4 + p_cnt + 2:]
                except (IndexError, ValueError):
                    raise InputError(f"{path}:{n}: not an index.noun line")
                if len(offsets) != synset_cnt:
                    raise InputError(f"{path}:{n}: expected {synset_cnt} offsets, found {len(offsets)}")
                self.index[fields[0]] = offsets

    def _read_data(self, path: str) -> None:
        # offset lex_filenum ss_type w_cnt word lex_id [...] p_cnt [ptr offset pos src/tgt]... | gloss
        with open(path, encoding="utf-8") as f:
            for n, line in enumerate(f, 1):
                if line.startswith("  ") or not line.strip():
                    continue
                body, _, gloss = line.partition(" | ")
                fields = body.split()
                try:
                    offset = fields[0]
                    w_cnt = int(fields[3], 16)
                    words = [fields[4 + 2 * i] for i in range(w_cnt)]
                    i = 4 + 2 * w_cnt
                    p_cnt = int(fields[i])
                    i += 1
                    hypernyms = []
                    for _ in range(p_cnt):
                        symbol, target, pos = fields[i], fields[i + 1], fields[i + 2]
                        if symbol in ("@", "@i") and pos == "n":
                            hypernyms.append(target)
                        i += 4
                except (IndexError, ValueError):
                    raise InputError(f"{path}:{n}: not a data.noun line")
                self.synsets[offset] = (words, hypernyms, gloss.strip())

    def _read_exceptions(self, path: str) -> None:
        with open(path, encoding="utf-8") as f:
            for line in f:
                fields = line.split()
                if len(fields) >= 2:
                    self.exceptions.append((fields[0], fields[1:]))

    def sense(self, lemma: str, number: int) -> str | None:
        """The offset of the number-th (1-based) sense of lemma, NLTK's lemma.n.NN."""
        offsets = self.index.get(lemma)
        if not offsets or not 1 <= number <= len(offsets):
            return None
        return offsets[number - 1]

    def nearest(self, offset: str, wanted) -> set[str]:
        """The synsets in wanted that are reachable from offset over hypernym (@) and
        instance-hypernym (@i) pointers without passing through another synset in wanted.
        (Every wanted ancestor is one of these or an ancestor of one of these.)"""
        found: set[str] = set()
        seen: set[str] = set()
        stack = [offset]
        while stack:
            for parent in self.synsets[stack.pop()][1]:
                if parent in seen:
                    continue
                seen.add(parent)
                if parent in wanted:
                    found.add(parent)
                else:
                    stack.append(parent)
        return found


def match_key(phrase: str) -> str:
    """The form in which two phrases are the same word for the grounding stage, which
    reads '-', '_' and '.' as spaces: "ash-bin" and "ash bin" are one phrase."""
    return " ".join(re.sub(r"[-_.]", " ", phrase).split())


def lemma_phrase(word: str) -> str:
    """A data.noun word as a phrase: '_' -> ' ', adjective markers like '(a)' removed."""
    return MARKER_RE.sub("", word).replace("_", " ").strip()


def lemma_rejection(phrase: str) -> str | None:
    """Why a WordNet lemma is not taken as a synonym, or None if it is acceptable."""
    if any(c.isupper() for c in phrase):
        return "proper noun or acronym (capitalised in WordNet)"
    if len(phrase) == 1:
        return "single letter"
    if any(c.isdigit() for c in phrase):
        return "contains a number"
    if not TERM_RE.match(phrase):
        return "unusual characters"
    if phrase in BLOCKED_SYNONYMS:
        return "blocklist: " + BLOCKED_SYNONYMS[phrase]
    return None


# ---------------------------------------------------------------- hand-written inputs

def read_rows(path: str, min_fields: int, max_fields: int):
    """(line number, fields) of each non-comment line of a tab-separated file. A field
    (other than the first) that starts with '#' begins a comment that runs to the end
    of the line; missing trailing fields are empty."""
    if not os.path.isfile(path):
        raise InputError(f"input file not found: {path}")
    with open(path, encoding="utf-8") as f:
        for n, raw in enumerate(f, 1):
            line = raw.rstrip("\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            fields = line.split("\t")
            for i in range(1, len(fields)):
                if fields[i].lstrip().startswith("#"):
                    fields = fields[:i]  # a trailing comment
                    break
            if not min_fields <= len(fields) <= max_fields:
                raise InputError(f"{path}:{n}: expected {min_fields} to {max_fields} tab-separated "
                                 f"fields, found {len(fields)}: {line!r}")
            yield n, [x.strip() for x in fields]


def check_phrase(path: str, n: int, phrase: str, what: str) -> str:
    if not TERM_RE.match(phrase):
        raise InputError(f"{path}:{n}: {what} {phrase!r} is not lower-case words separated by single spaces")
    return phrase


def split_list(path: str, n: int, field: str, what: str) -> list[str]:
    if not field:
        return []
    return [check_phrase(path, n, x.strip(), what) for x in field.split("|")]


class Concept:
    def __init__(self, term: str, offset: str | None, sense: str):
        self.term = term          # the seed term that names the concept
        self.offset = offset      # its WordNet synset, None for '-'
        self.sense = sense        # 'lemma.n.NN' or '-'
        self.seeds: list[str] = []          # other seed terms with the same sense
        self.wordnet: list[str] = []        # acceptable WordNet lemmas of the synset
        self.extra_synonyms: list[str] = []
        self.extra_hypernyms: list[str] = []  # terms, as written in extra.txt
        self.synonyms: list[str] = []
        self.hypernyms: list[str] = []


def read_categories(path: str, wn: WordNet):
    concepts: dict[str, Concept] = {}  # by term
    by_offset: dict[str, Concept] = {}
    alias: dict[str, str] = {}  # any seed term -> the term of its concept
    for n, (term, sense) in read_rows(path, 2, 2):
        check_phrase(path, n, term, "term")
        if term in alias:
            raise InputError(f"{path}:{n}: term {term!r} is listed twice")
        if sense == "-":
            concepts[term] = Concept(term, None, "-")
            alias[term] = term
            continue
        m = SENSE_RE.match(sense)
        if not m:
            raise InputError(f"{path}:{n}: sense {sense!r} is not lemma.n.NN or '-'")
        lemma, number = m.group("lemma"), int(m.group("num"))
        if lemma not in wn.index:
            raise InputError(f"{path}:{n}: WordNet has no noun {lemma!r}")
        offset = wn.sense(lemma, number)
        if offset is None:
            count = len(wn.index[lemma])
            raise InputError(f"{path}:{n}: WordNet's noun {lemma!r} has {count} "
                             f"sense{'s' if count != 1 else ''}, not {number}")
        if offset in by_offset:
            # Same synset as an earlier seed: one concept, named by the earlier term.
            first = by_offset[offset]
            first.seeds.append(term)
            alias[term] = first.term
            continue
        c = Concept(term, offset, sense)
        concepts[term] = c
        by_offset[offset] = c
        alias[term] = term
    return concepts, by_offset, alias


def read_extra(path: str, concepts: dict[str, Concept], alias: dict[str, str]) -> None:
    seen: set[str] = set()
    for n, fields in read_rows(path, 2, 3):
        term = check_phrase(path, n, fields[0], "term")
        if term not in alias:
            raise InputError(f"{path}:{n}: {term!r} is not a term of categories.txt")
        if term in seen:
            raise InputError(f"{path}:{n}: {term!r} has two lines")
        seen.add(term)
        c = concepts[alias[term]]
        c.extra_synonyms += split_list(path, n, fields[1], "synonym")
        for h in split_list(path, n, fields[2] if len(fields) > 2 else "", "hypernym"):
            if h not in alias:
                raise InputError(f"{path}:{n}: hypernym {h!r} is not a term of categories.txt")
            c.extra_hypernyms.append(h)


# ---------------------------------------------------------------- building

def regular_plurals(word: str) -> set[str]:
    forms = {word + "s", word + "es"}
    if word.endswith("y"):
        forms.add(word[:-1] + "ies")
    return forms


def build(wn: WordNet, concepts: dict[str, Concept], by_offset: dict[str, Concept],
          alias: dict[str, str]):
    report = {"dropped": [], "rejected": [], "shared": [], "plural_conflicts": []}

    # 1. WordNet lemmas of each chosen synset, after the lemma hygiene rules.
    for c in concepts.values():
        if c.offset is None:
            continue
        for word in wn.synsets[c.offset][0]:
            phrase = lemma_phrase(word)
            if phrase == c.term or phrase in c.seeds:
                continue  # the concept's own terms
            why = lemma_rejection(phrase)
            if why:
                report["rejected"].append((c.term, phrase, why))
            elif phrase not in c.wordnet:
                c.wordnet.append(phrase)

    # 2. Who claims each phrase: its concept's term, a merged seed, an extra synonym
    #    (explicit claims), or a WordNet lemma (implicit claim). Phrases are compared
    #    by match_key, as the Rust side reads them ("living-room" is "living room").
    claims: dict[str, set[str]] = {}
    for c in concepts.values():
        for phrase in [c.term, *c.seeds, *c.extra_synonyms]:
            claims.setdefault(match_key(phrase), set()).add(c.term)

    # 3. The collision rule: a WordNet lemma that another concept claims explicitly (as
    #    its term, a seed or an extra synonym) is dropped, unless this concept claims it
    #    explicitly too. A lemma two concepts share only through WordNet ("closet" for a
    #    cupboard and a wardrobe) is kept in both: grounding then refuses it as ambiguous
    #    where a scene has both, and reads it where a scene has one.
    for c in concepts.values():
        explicit = {match_key(x) for x in [c.term, *c.seeds, *c.extra_synonyms]}
        keep = []
        for phrase in c.wordnet:
            others = sorted(claims.get(match_key(phrase), set()) - {c.term})
            if others and match_key(phrase) not in explicit:
                report["dropped"].append((c.term, phrase, others))
            else:
                keep.append(phrase)
        # One spelling per match key, the term's own key excluded; where WordNet has
        # both "ash bin" and "ash-bin", the spaced one is kept.
        by_key: dict[str, str] = {}
        for phrase in [*keep, *c.seeds, *c.extra_synonyms]:
            k = match_key(phrase)
            if k == match_key(c.term):
                continue
            if k not in by_key or ("-" in by_key[k], by_key[k]) > ("-" in phrase, phrase):
                by_key[k] = phrase
        c.synonyms = sorted(by_key.values())
    # Phrases that stay with more than one concept (only explicit ones can): reported.
    holders: dict[str, set[str]] = {}
    for c in concepts.values():
        for phrase in [c.term, *c.synonyms]:
            holders.setdefault(match_key(phrase), set()).add(c.term)
    for c in concepts.values():
        for phrase in c.synonyms:
            others = sorted(holders[match_key(phrase)] - {c.term})
            if others:
                report["shared"].append((c.term, phrase, others))

    # 4. Hypernyms. Direct links: the nearest seed concepts above the synset in
    #    WordNet's hypernym graph, and extra.txt's hypernyms; BLOCKED_HYPERNYMS removes
    #    a direct link. Each concept's hypernyms are then the transitive closure of the
    #    direct links, which is WordNet's hypernym closure restricted to seed concepts
    #    when nothing is blocked. Blocking (term, hyper) therefore also keeps hyper away
    #    from the terms below term, unless they reach it another way.
    direct: dict[str, set[str]] = {}
    for c in concepts.values():
        parents: set[str] = set()
        if c.offset is not None:
            parents = {by_offset[a].term for a in wn.nearest(c.offset, by_offset)}
        parents |= {alias[h] for h in c.extra_hypernyms}
        parents.discard(c.term)
        direct[c.term] = {p for p in parents if (c.term, p) not in BLOCKED_HYPERNYMS}

    closed: dict[str, set[str]] = {}

    def closure(term: str, path: tuple[str, ...]) -> set[str]:
        if term in closed:
            return closed[term]
        if term in path:
            raise InputError("hypernym cycle: " + " -> ".join(path[path.index(term):] + (term,)))
        result: set[str] = set()
        for p in direct[term]:
            result.add(p)
            result |= closure(p, path + (term,))
        result.discard(term)
        closed[term] = result
        return result

    for term in sorted(concepts):
        closure(term, ())
    for term, hyper in sorted(BLOCKED_HYPERNYMS):
        if term not in concepts or hyper not in concepts:
            raise InputError(f"BLOCKED_HYPERNYMS entry ({term!r}, {hyper!r}) names a term that "
                             f"is not a concept of categories.txt")
    for c in concepts.values():
        # Most specific first: a hypernym with more hypernyms of its own is nearer.
        c.hypernyms = sorted(closed[c.term], key=lambda h: (-len(closed[h]), h))

    # 5. Irregular plurals from noun.exc, for every phrase of the lexicon.
    phrases: set[str] = set()
    for c in concepts.values():
        phrases.add(c.term)
        phrases.update(c.synonyms)
    irregular: dict[str, set[str]] = {}  # singular -> plurals (single words and noun.exc phrases)
    for plural, singulars in wn.exceptions:
        p = plural.replace("_", " ")
        for s in singulars:
            s = s.replace("_", " ")
            if p != s and p not in regular_plurals(s):
                irregular.setdefault(s, set()).add(p)
    plurals: set[tuple[str, str]] = set()
    for phrase in phrases:
        for p in irregular.get(phrase, ()):
            plurals.add((p, phrase))
        head, _, last = phrase.rpartition(" ")
        # Formed on the last word, except where the last word is not the head noun
        # ("staff of life", "bar of soap": the plural changes the first noun).
        if head and " of " not in f" {phrase} ":
            for p in irregular.get(last, ()):
                plurals.add((f"{head} {p}", phrase))
    for p, singular in sorted(plurals):
        last_p, last_s = p.split(" ")[-1], singular.split(" ")[-1]
        if (last_p, last_s) in BLOCKED_PLURALS:
            plurals.discard((p, singular))
    # A plural that is itself a phrase of the lexicon would shadow it: leave it out.
    keys = {match_key(x) for x in phrases}
    for p, s in sorted(plurals):
        if match_key(p) in keys:
            report["plural_conflicts"].append((p, s))
            plurals.discard((p, s))
    return report, sorted(plurals)


def coverage(concepts: dict[str, Concept], plurals, examples_dir: str | None) -> list[str]:
    """Words that must resolve (ProcTHOR types and rooms, example object names) but do not."""
    known: set[str] = set()
    for c in concepts.values():
        known.add(match_key(c.term))
        known.update(match_key(x) for x in c.synonyms)
    known.update(match_key(p) for p, _ in plurals)

    def resolves(word: str) -> bool:
        if word in known:
            return True
        head, _, last = word.rpartition(" ")
        for s in known:
            s_head, _, s_last = s.rpartition(" ")
            if s_head == head and word in {f"{head} {x}".strip() for x in regular_plurals(s_last)}:
                return True
        return False

    wanted = {f"ProcTHOR type {k}": v for k, v in PROCTHOR_TYPES.items()}
    wanted.update({f"ProcTHOR room {k}": v for k, v in PROCTHOR_ROOMS.items()})
    if examples_dir and os.path.isdir(examples_dir):
        for path in sorted(glob.glob(os.path.join(examples_dir, "*.json"))):
            with open(path, encoding="utf-8") as f:
                scene = json.load(f)
            for obj in scene.get("objects", []):
                name = match_key(re.sub(r"\s+\d+$", "", str(obj.get("name", ""))).lower())
                if name:
                    wanted[f"{os.path.basename(path)} object {name!r}"] = name
    return sorted(f"{k} ({v!r})" for k, v in wanted.items() if not resolves(v))


# ---------------------------------------------------------------- output

LICENCE = """\
This software and database is being provided to you, the LICENSEE, by
Princeton University under the following license.  By obtaining, using
and/or copying this software and database, you agree that you have
read, understood, and will comply with these terms and conditions.:

Permission to use, copy, modify and distribute this software and
database and its documentation for any purpose and without fee or
royalty is hereby granted, provided that you agree to comply with
the following copyright notice and statements, including the disclaimer,
and that the same appear on ALL copies of the software, database and
documentation, including modifications that you make for internal
use or for distribution.

WordNet 3.0 Copyright 2006 by Princeton University.  All rights reserved.

THIS SOFTWARE AND DATABASE IS PROVIDED "AS IS" AND PRINCETON
UNIVERSITY MAKES NO REPRESENTATIONS OR WARRANTIES, EXPRESS OR
IMPLIED.  BY WAY OF EXAMPLE, BUT NOT LIMITATION, PRINCETON
UNIVERSITY MAKES NO REPRESENTATIONS OR WARRANTIES OF MERCHANT-
ABILITY OR FITNESS FOR ANY PARTICULAR PURPOSE OR THAT THE USE
OF THE LICENSED SOFTWARE, DATABASE OR DOCUMENTATION WILL NOT
INFRINGE ANY THIRD PARTY PATENTS, COPYRIGHTS, TRADEMARKS OR
OTHER RIGHTS.

The name of Princeton University or Princeton may not be used in
advertising or publicity pertaining to distribution of the software
and/or database.  Title to copyright in this software, database and
any associated documentation shall at all times remain with
Princeton University and LICENSEE agrees to preserve same."""


def render(concepts: dict[str, Concept], plurals, digest: str) -> str:
    out = [
        "# GENERATED FILE - do not edit by hand.",
        f"# Regenerate from the repository root with: {COMMAND}",
        "# (the script, its inputs and the rules are described in tools/lexicon/README.md).",
        "#",
        "# Built from WordNet 3.0's noun database (data.noun, index.noun, noun.exc as shipped",
        f"# by Debian's package wordnet-base; sha256 of the three files in that order,",
        f"# concatenated, begins {digest})",
        "# and the hand-written tools/lexicon/categories.txt and tools/lexicon/extra.txt.",
        "#",
        "# Format: term<TAB>synonyms<TAB>hypernyms, lists separated by '|'; hypernyms are other",
        "# terms of this file, most specific first. '~plural<TAB>singular' lines give irregular",
        "# plurals (regular -s/-es/-ies plurals are not listed).",
        "#",
        "# This file contains data derived from WordNet 3.0, used under the WordNet 3.0 licence:",
        "# WordNet 3.0 Copyright 2006 by Princeton University. All rights reserved.",
        "# (George A. Miller (1995). WordNet: A Lexical Database for English.",
        "# Communications of the ACM 38(11): 39-41. https://wordnet.princeton.edu/)",
        "# The licence, which must accompany copies of the database and works derived from it:",
        "#",
    ]
    out += [("# " + line).rstrip() for line in LICENCE.split("\n")]
    out.append("")
    for term in sorted(concepts):
        c = concepts[term]
        out.append(f"{c.term}\t{'|'.join(c.synonyms)}\t{'|'.join(c.hypernyms)}")
    out.append("")
    for plural, singular in plurals:
        out.append(f"~{plural}\t{singular}")
    return "\n".join(out) + "\n"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description="Build the grounding lexicon from WordNet 3.0.")
    ap.add_argument("--wordnet", default=DEFAULT_WORDNET, metavar="DIR",
                    help=f"directory with data.noun, index.noun, noun.exc (default {DEFAULT_WORDNET})")
    ap.add_argument("--out", default=DEFAULT_OUT, metavar="FILE",
                    help="output file (default crates/shenlong/src/ground/lexicon.txt)")
    ap.add_argument("--categories", default=DEFAULT_CATEGORIES, metavar="FILE",
                    help="seed list (default tools/lexicon/categories.txt)")
    ap.add_argument("--extra", default=DEFAULT_EXTRA, metavar="FILE",
                    help="hand additions (default tools/lexicon/extra.txt)")
    ap.add_argument("--examples", default=DEFAULT_EXAMPLES, metavar="DIR",
                    help="example scenes whose object names must resolve (default examples/; "
                         "'' to skip)")
    ap.add_argument("--explain", action="store_true",
                    help="also print each seed's sense, WordNet lemmas and gloss to stderr")
    ap.add_argument("-q", "--quiet", action="store_true",
                    help="do not print the report of dropped and rejected lemmas")
    args = ap.parse_args(argv)
    try:
        wn = WordNet(args.wordnet)
        concepts, by_offset, alias = read_categories(args.categories, wn)
        read_extra(args.extra, concepts, alias)
        report, plurals = build(wn, concepts, by_offset, alias)
    except InputError as e:
        note(str(e))
        return 2

    if args.explain:
        for term in sorted(concepts):
            c = concepts[term]
            if c.offset is None:
                print(f"{term}\t-", file=sys.stderr)
            else:
                words, _, gloss = wn.synsets[c.offset]
                print(f"{term}\t{c.sense}\t[{', '.join(words)}]\t{gloss}", file=sys.stderr)
    if not args.quiet:
        for term, phrase, others in report["dropped"]:
            note(f"collision: dropped {phrase!r} from {term!r} (also claimed by {', '.join(others)})")
        for term, phrase, others in report["shared"]:
            note(f"shared on purpose (extra.txt): {phrase!r} is a synonym of {term!r} and also "
                 f"the term or a synonym of {', '.join(others)}")
        for term, phrase, why in report["rejected"]:
            note(f"rejected {phrase!r} for {term!r}: {why}")
        for p, s in report["plural_conflicts"]:
            note(f"plural {p!r} of {s!r} left out: it is itself a phrase of the lexicon")

    missing = coverage(concepts, plurals, args.examples or None)
    if missing:
        note(f"{len(missing)} required word(s) do not resolve to a concept (add them to "
             f"categories.txt or extra.txt): " + "; ".join(missing))
        return 2
    text = render(concepts, plurals, wn.digest())

    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    tmp = args.out + ".tmp"
    with open(tmp, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)
    os.replace(tmp, args.out)
    n_concepts = len(concepts)
    note(f"wrote {args.out}: {n_concepts} concept lines, {len(plurals)} plural lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
