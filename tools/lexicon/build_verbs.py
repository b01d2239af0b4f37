#!/usr/bin/env python3
"""Writes crates/shenlong/src/ground/verbs.txt: the verbs that move an object to a place,
distilled from WordNet 3.0's verb database (Debian's wordnet-base).

A verb is kept when one of its senses
  - is a troponym (WordNet's '@' pointer, followed up to two levels) of "move, displace"
    (move#2: cause to move or shift into a new position or place) or of "put, set, place"
    (put#1), and
  - has the caused-motion frame "Somebody ----s something PP" or "Somebody ----s somebody
    PP" (frames 21 and 20), which is what "park the car in the yard" needs;
then verbs_exclude.txt removes those whose everyday sense is not relocating an object
(aim, hit, banish, …) and verbs_extra.txt adds the few WordNet files elsewhere (tuck,
budge, scoot). Irregular forms come from verb.exc. The output is sorted and depends only
on the inputs. Usage: python3 tools/lexicon/build_verbs.py [--wordnet DIR] [--out FILE]
"""
import argparse
import hashlib
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def fail(msg):
    print(f"build_verbs: {msg}", file=sys.stderr)
    sys.exit(2)


def read_list(path):
    out = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            if not re.fullmatch(r"[a-z]+", line):
                fail(f"{path}:{n}: not a lower-case word: {line!r}")
            out.append(line)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--wordnet", default="/usr/share/wordnet")
    ap.add_argument("--out", default=os.path.join(ROOT, "crates/shenlong/src/ground/verbs.txt"))
    args = ap.parse_args()
    paths = [os.path.join(args.wordnet, n) for n in ("data.verb", "index.verb", "verb.exc")]
    for p in paths:
        if not os.path.exists(p):
            fail(f"missing {p} (apt-get install wordnet-base)")
    syn = {}
    with open(paths[0], encoding="latin-1") as f:
        for line in f:
            if line.startswith("  "):
                continue
            fields = line.split("| ")[0].split()
            off, wc = fields[0], int(fields[3], 16)
            lemmas = [re.sub(r"\(.*\)", "", fields[4 + 2 * i].lower()) for i in range(wc)]
            p = 4 + 2 * wc
            pc = int(fields[p])
            hypernyms = []
            for i in range(pc):
                sym, o, pos, _ = fields[p + 1 + 4 * i : p + 5 + 4 * i]
                if sym == "@" and pos == "v":
                    hypernyms.append(o)
            q = p + 1 + 4 * pc
            frames = set()
            if q < len(fields):
                for i in range(int(fields[q])):
                    frames.add(int(fields[q + 2 + 3 * i]))
            syn[off] = (lemmas, hypernyms, frames)
    index = {}
    with open(paths[1], encoding="latin-1") as f:
        for line in f:
            if line.startswith(" "):
                continue
            fields = line.split()
            pc = int(fields[3])
            index[fields[0]] = fields[4 + pc + 2 :]
    try:
        seeds = {index["move"][1], index["put"][0]}
    except (KeyError, IndexError):
        fail("WordNet has no move#2 or put#1")

    def depth(o, d=0):
        if o in seeds:
            return d
        if d >= 2:
            return None
        found = [x for x in (depth(h, d + 1) for h in syn[o][1]) if x is not None]
        return min(found) if found else None

    verbs = set()
    for o, (lemmas, _, frames) in syn.items():
        if depth(o) is not None and frames & {20, 21}:
            verbs.update(l for l in lemmas if re.fullmatch(r"[a-z]+", l))
    exclude = set(read_list(os.path.join(HERE, "verbs_exclude.txt")))
    extra = read_list(os.path.join(HERE, "verbs_extra.txt"))
    verbs = (verbs - exclude) | set(extra)
    irregular = []
    with open(paths[2], encoding="latin-1") as f:
        for line in f:
            parts = line.split()
            if len(parts) >= 2 and parts[1] in verbs and re.fullmatch(r"[a-z]+", parts[0]):
                irregular.append((parts[0], parts[1]))
    digest = hashlib.sha256(b"".join(open(p, "rb").read() for p in paths)).hexdigest()[:16]
    tmp = args.out + ".tmp"
    with open(tmp, "w", encoding="utf-8") as out:
        out.write("# GENERATED FILE - do not edit by hand.\n")
        out.write("# Regenerate from the repository root with: python3 tools/lexicon/build_verbs.py\n")
        out.write("# Verbs that move an object to a place, from WordNet 3.0's data.verb, index.verb\n")
        out.write(f"# and verb.exc (sha256 of the three, concatenated, begins {digest}), less\n")
        out.write("# tools/lexicon/verbs_exclude.txt, plus tools/lexicon/verbs_extra.txt.\n")
        out.write("# WordNet 3.0 Copyright 2006 by Princeton University, used under the WordNet 3.0\n")
        out.write("# licence (reproduced in full in lexicon.txt beside this file).\n")
        out.write("# Format: one verb a line; '~form<TAB>verb' lines give irregular forms.\n")
        for v in sorted(verbs):
            out.write(v + "\n")
        for form, v in sorted(irregular):
            out.write(f"~{form}\t{v}\n")
    os.replace(tmp, args.out)
    print(f"build_verbs: {len(verbs)} verbs, {len(irregular)} irregular forms", file=sys.stderr)


if __name__ == "__main__":
    main()
