#!/usr/bin/python3
# Debian's python3-* packages are visible only to /usr/bin/python3 (not to a
# pyenv/venv interpreter that may come first on PATH), hence the absolute
# shebang.  This script nevertheless uses only the Python standard library.
#
# SPDX-License-Identifier: GPL-3.0-or-later
"""
foamConformance.py -- prove nmmDictionary's FoamFile reader against OpenFOAM.

For every dictionary of a file set the script runs the real OpenFOAM reader
(`foamDictionary -expand FILE`, OpenFOAM v1912 as packaged by Debian) and
`nmmDictionary -expand FILE`, parses both outputs with the small independent
FoamFile parser below and compares the two trees semantically.

File sets
---------
  --examples        OpenFOAM's tutorials as shipped in the Debian package
                    openfoam-examples (/usr/share/doc/openfoam-examples/examples).
                    The tree is first materialised into a scratch copy:
                      * *.gz files (Debian compresses ~450 of them) are
                        decompressed to their plain name;
                      * symbolic links to files are copied as regular files
                        holding the target's content (a region's fvSchemes
                        that links to another region's is still read in its
                        own directory, as a solver would);
                      * symbolic links to directories are NOT followed: they
                        point to whole tutorial cases that are already part
                        of the tree (e.g. mesh/snappyHexMesh/motorBike ->
                        incompressible/simpleFoam/motorBike);
                      * dangling or looping links are reported and dropped.
  --tree DIR...     every dictionary below the given directories (the
                    project's tutorials and test cases).
  FILE...           explicit files, taken whatever their path or name (the
                    content rules below still apply); a directory given
                    here is walked as with --tree.

In --examples and --tree mode a file is a candidate only if it lies in a
`system`, `constant` or time directory (`0`, `0.orig`, `0.kEpsilon`, or a
number such as `-180`) of a case, i.e. of a directory that holds a `system`
or `constant` directory; files of the project's tricky suite
(tests/conformance/tricky) are candidates as well.  Files outside such
folders are counted as not-in-case-dir (Allrun scripts, READMEs, geometry
resources, OpenFOAM's own parser test files in IO/dictionary, ...).
Candidates are then EXCLUDED, each with its counted reason, when
  mesh-or-geometry   a path component is polyMesh (points/faces/owner/...),
                     triSurface or extendedFeatureEdgeMesh (surface geometry),
                     or boundaryData (raw mapped-boundary data lists);
  non-dictionary-ext the extension marks a non-dictionary: *.m4 (templates
                     expanded by m4 before use), *.stl/*.obj/*.vtk/*.vtp/
                     *.eMesh/*.ftr/*.nas (geometry), *.dat/*.csv/*.xy/*.txt/
                     *.inp (data tables), scripts, images, ...;
  binary             the file holds NUL bytes (a header saying `format
                     binary` over text content is read like any other: about
                     120 tutorial fields are written that way);
  no-header          the file does not start with a FoamFile header (include
                     fragments such as 0.orig/include/initialConditions: they
                     are still exercised through the files that include them);
  not-a-dictionary   the header is followed by a bare list rather than
                     keyword entries (cloud positions, labelList, vectorField);
  unreadable         the file could not be read or decoded.

For --examples (openfoam-examples 1912) that gives: 7,880 files materialised
(451 decompressed, 4 directory links not followed), 947 not-in-case-dir,
180 mesh-or-geometry, 57 non-dictionary-ext, 203 no-header, 16
not-a-dictionary, 0 binary: 6,477 dictionaries are checked (of the 6,816
files in system/, constant/ and 0*/ folders).  Of these, 21 use #calc,
#codeStream or #{ #} and 10 are rejected by foamDictionary itself (they
include files an Allrun script creates, or are fragments meant for another
file's scope).

Running the readers
-------------------
Both readers run with the working directory set to the file's case directory
and the file given relative to it (e.g. `system/controlDict`), which is how a
solver opens it: relative #include paths resolve against the including file,
$FOAM_CASE (set by foamDictionary from its working directory) is the case.
Files outside a case run in their own directory.  The OpenFOAM environment is
taken once from /usr/share/openfoam/etc/bashrc (WM_PROJECT_DIR is what
#includeEtc / #includeFunc need) and handed to both readers.  foamDictionary
is run with `-precision 15` (--foam-precision) so the reference values are
not rounded to the default 6 digits; the tolerance below applies anyway.
Note that the precision also changes what `#eval "$x"` computes with: v1912
substitutes $x as text written at that precision.  PWD is set to the working
directory (OpenFOAM warns otherwise).  OpenFOAM prints warnings on stdout,
before the banner: they are cut off before parsing (and shown as notes).
foamDictionary takes 10-15 ms per file; the examples run (about 6,500 files)
takes 1 to 1.5 minutes on 2 cores.

Classification of a file
------------------------
  agreed               both trees are equal after the normalisations below
  skipped-unsupported  the file, or a file it includes, uses #calc,
                       #codeStream or a verbatim `#{ ... #}` code block
                       (checked before running anything)
  skipped-foam-rejects foamDictionary exits non-zero or prints FATAL
  disagreed            the trees differ
  nmm-error            nmmDictionary fails (non-zero exit, FATAL, timeout or
                       unparsable output) where foamDictionary succeeded;
                       counted as a disagreement
  harness-error        the reference output could not be parsed here (a bug
                       of this script); counted as a failure

Comparison rules
----------------
  * dictionaries: same keyword set at every level; order is ignored (an order
    difference is reported as a note only); a dictionary versus a primitive
    entry is a difference; duplicate keywords in an output are a difference.
  * primitive entries are token streams with nested ( ), [ ] and { } groups;
    numbers compare numerically with relative tolerance --rtol (default
    1e-5: OpenFOAM prints 6 significant digits by default), so 1, 1.0 and
    1e0 are equal; a sized list `N( ... )` loses its size when N matches the
    element count (for lists of `name { ... }` pairs a pair counts as one);
    a uniform list `N{v}` equals N copies of v.
  * words and quoted strings compare as text.  foamDictionary keeps the
    quoting of the source ("quoted" stays quoted, $var of a string gives a
    string, a keyword keeps the quoting of its first definition), and
    OpenFOAM reads a word from a string token and vice versa, so a quoting
    difference alone is a note, not a disagreement (--strict-quotes makes it
    one).  Escapes are decoded as OpenFOAM reads them (\\" is a quote).
  * the FoamFile header is compared only when both outputs have it, and its
    `note` and `location` entries are ignored (foamDictionary prints them as
    read but writers are free to set them); `version 2.0` prints as `2`.
    v1912 keeps only the header of the file read: headers of included files
    and FoamFile entries of sub-dictionaries are dropped, so an nmm output
    that keeps them disagrees.
  * comments and the banner are ignored.

Testing the harness itself: --selftest checks the comparator on built-in
pairs that must agree and perturbations that must not (a wrong number, a
missing key, ...); --self-compare runs a whole file set with, in place of
nmmDictionary, this script's own rendering of foamDictionary's parsed output
read back by foamDictionary (all examples agree that way).

Exit status: 0 when nothing disagreed, 1 on any disagreement / nmm-error /
harness-error, 2 on a usage or environment problem (e.g. OpenFOAM missing).
"""

import argparse
import concurrent.futures
import gzip
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TRICKY_DIR = os.path.join(HERE, "tricky")

DEFAULT_BASHRC = "/usr/share/openfoam/etc/bashrc"
DEFAULT_EXAMPLES = "/usr/share/doc/openfoam-examples/examples"
INSTALL_HINT = ("install the Debian packages listed in etc/debianPackages "
                "(openfoam, openfoam-examples), e.g. "
                "`apt-get install openfoam openfoam-examples`")

FOAM_PRECISION = 15
CALL_TIMEOUT = 120  # seconds for one reader call

EXCLUDED_DIRS = {
    "polyMesh": "mesh-or-geometry",
    "triSurface": "mesh-or-geometry",
    "extendedFeatureEdgeMesh": "mesh-or-geometry",
    "boundaryData": "mesh-or-geometry",
}
EXCLUDED_EXTS = {
    ".m4", ".stl", ".stlb", ".obj", ".vtk", ".vtp", ".vtu", ".eMesh", ".ftr",
    ".nas", ".fms", ".fmsh", ".ac", ".off", ".smesh", ".dat", ".csv", ".xy",
    ".txt", ".inp", ".raw", ".sh", ".py", ".png", ".jpg", ".jpeg", ".gif",
    ".pdf", ".svg", ".md", ".foam", ".OpenFOAM", ".gz", ".tgz", ".zip",
    ".swp", ".json", ".xml", ".html", ".gnuplot", ".plt",
}
UNSUPPORTED_RE = re.compile(r"#calc\b|#codeStream\b|#\{")


def die(msg, code=2):
    sys.stderr.write("foamConformance: %s\n" % msg)
    sys.exit(code)


# ---------------------------------------------------------------------------
# OpenFOAM environment
# ---------------------------------------------------------------------------

def foam_environment(bashrc):
    """Environment of an OpenFOAM shell, computed once (sourcing bashrc for
    every call would cost a bash start-up per file)."""
    if not os.path.isfile(bashrc):
        die("OpenFOAM is not installed (no %s): %s" % (bashrc, INSTALL_HINT))
    # bashrc parses its own arguments ("$@") as settings: source it with
    # none (passing the path as $1 makes Debian's bashrc recurse).
    penv = dict(os.environ)
    penv["NMM_FOAM_BASHRC"] = bashrc
    proc = subprocess.run(
        ["bash", "-c", 'f="$NMM_FOAM_BASHRC"; unset NMM_FOAM_BASHRC; set --; '
                       '. "$f" >/dev/null 2>&1; env -0'],
        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
        stdin=subprocess.DEVNULL, env=penv, timeout=60)
    env = {}
    for item in proc.stdout.split(b"\0"):
        if b"=" in item:
            k, v = item.split(b"=", 1)
            env[k.decode(errors="replace")] = v.decode(errors="replace")
    if "WM_PROJECT_DIR" not in env:
        env["WM_PROJECT_DIR"] = os.path.dirname(os.path.dirname(bashrc))
    for k in ("FOAM_CASE", "FOAM_CASENAME"):
        env.pop(k, None)
    exe = shutil.which("foamDictionary", path=env.get("PATH", os.defpath))
    if not exe:
        die("foamDictionary not found on the OpenFOAM PATH: " + INSTALL_HINT)
    return env, exe


# ---------------------------------------------------------------------------
# File collection
# ---------------------------------------------------------------------------

class Collection:
    def __init__(self):
        self.files = []          # (abs path, case dir)
        self.excluded = {}       # reason -> [paths]
        self.notes = []          # messages about the materialised copy

    def exclude(self, reason, path):
        self.excluded.setdefault(reason, []).append(path)


def materialise_examples(src, dst, coll):
    """Copy src to dst resolving file symlinks and decompressing *.gz."""
    if not os.path.isdir(src):
        die("OpenFOAM examples not found (%s): %s" % (src, INSTALL_HINT))
    n_copied = n_gz = 0
    for root, dirs, files in os.walk(src):
        rel = os.path.relpath(root, src)
        out = os.path.normpath(os.path.join(dst, rel))
        os.makedirs(out, exist_ok=True)
        for d in list(dirs):
            if os.path.islink(os.path.join(root, d)):
                coll.exclude("directory-symlink (case already in tree)",
                             os.path.normpath(os.path.join(rel, d)))
                dirs.remove(d)
        plain = set(files)
        for f in files:
            s = os.path.join(root, f)
            try:
                real = os.path.realpath(s, strict=True)
                if not os.path.isfile(real):
                    raise OSError("not a regular file")
            except OSError:
                coll.exclude("dangling-or-looping-symlink",
                             os.path.normpath(os.path.join(rel, f)))
                continue
            if f.endswith(".gz"):
                name = f[:-3]
                if name in plain:
                    coll.notes.append("both %s and %s.gz exist: kept the plain"
                                      " file" % (os.path.join(rel, name), name))
                    continue
                try:
                    with gzip.open(real, "rb") as g:
                        data = g.read()
                except (OSError, EOFError):
                    coll.exclude("bad-gzip",
                                 os.path.normpath(os.path.join(rel, f)))
                    continue
                with open(os.path.join(out, name), "wb") as h:
                    h.write(data)
                n_gz += 1
            else:
                shutil.copyfile(real, os.path.join(out, f))
                n_copied += 1
    coll.notes.append("materialised %d files (%d decompressed) into %s"
                      % (n_copied + n_gz, n_gz, dst))


def is_time_dir(name):
    """0, 0.orig, 0.kEpsilon ... and numeric time names such as -180."""
    if name.startswith("0"):
        return True
    try:
        float(name)
        return True
    except ValueError:
        return False


def is_case_dir(path):
    return (os.path.isdir(os.path.join(path, "system"))
            or os.path.isdir(os.path.join(path, "constant")))


def case_location(path):
    """(case dir, True) when path lies in system/constant/0* of a case,
    else (directory of the file, False)."""
    parts = os.path.abspath(path).split(os.sep)
    for i in range(1, len(parts) - 1):
        p = parts[i]
        if p in ("system", "constant") or is_time_dir(p):
            case = os.sep.join(parts[:i]) or os.sep
            if is_case_dir(case):
                return case, True
    return os.path.dirname(os.path.abspath(path)), False


HEADER_RE = re.compile(rb"\A(?:\s+|//[^\n]*\n?|/\*.*?\*/)*FoamFile"
                       rb"(?:\s+|//[^\n]*\n?|/\*.*?\*/)*\{(.*?)\}", re.S)
AFTER_RE = re.compile(rb"\A(?:\s+|//[^\n]*\n?|/\*.*?\*/)*(.)", re.S)


def content_exclusion(path, explicit):
    """Reason to exclude a file judged by its name and content, or None."""
    base = os.path.basename(path)
    if not explicit:
        for part in os.path.abspath(path).split(os.sep)[:-1]:
            if part in EXCLUDED_DIRS:
                return EXCLUDED_DIRS[part]
        ext = os.path.splitext(base)[1]
        if ext in EXCLUDED_EXTS or base.startswith("."):
            return "non-dictionary-ext"
    try:
        with open(path, "rb") as h:
            data = h.read()
    except OSError:
        return "unreadable"
    if b"\0" in data:
        return "binary"
    m = HEADER_RE.match(data)
    if not m:
        return "no-header"
    rest = AFTER_RE.match(data[m.end():])
    if rest and (rest.group(1) in b"(0123456789"):
        return "not-a-dictionary"
    return None


def collect(args, coll):
    def consider(path, explicit):
        if explicit:
            case, _ = case_location(path)
        else:
            case, in_case = case_location(path)
            tricky = os.path.abspath(path).startswith(TRICKY_DIR + os.sep)
            if not in_case and not tricky:
                coll.exclude("not-in-case-dir", path)
                return
            if tricky and not in_case:
                case = os.path.dirname(os.path.abspath(path))
        reason = content_exclusion(path, explicit)
        if reason:
            coll.exclude(reason, path)
        else:
            coll.files.append((os.path.abspath(path), case))

    def walk(top):
        for root, dirs, files in os.walk(top):
            dirs[:] = sorted(d for d in dirs if not d.startswith("."))
            for f in sorted(files):
                if f == MARKER:
                    continue
                p = os.path.join(root, f)
                if os.path.islink(p) and not os.path.exists(p):
                    coll.exclude("dangling-or-looping-symlink", p)
                    continue
                consider(p, False)

    if args.examples:
        walk(args.examples_root)
    for d in args.tree or []:
        if not os.path.isdir(d):
            die("--tree: not a directory: %s" % d)
        walk(d)
    for f in args.files:
        if os.path.isdir(f):
            walk(f)
        elif os.path.isfile(f):
            consider(f, True)
        else:
            die("no such file: %s" % f)


# ---------------------------------------------------------------------------
# Detection of unsupported constructs (follows includes, best effort)
# ---------------------------------------------------------------------------

INCLUDE_RE = re.compile(
    r'#(include|includeIfPresent|sinclude|includeEtc|sincludeEtc|includeFunc)'
    r'\s+("[^"]*"|[^\s;]+)')
COMMENT_RE = re.compile(r'"(?:[^"\\]|\\.)*"|//[^\n]*|/\*.*?\*/', re.S)


def strip_comments(text):
    return COMMENT_RE.sub(lambda m: m.group(0) if m.group(0)[0] == '"'
                          else " ", text)


def etc_dirs(env):
    d = os.path.join(env.get("WM_PROJECT_DIR", "/usr/share/openfoam"), "etc")
    return [d]


def find_function_object(name, env):
    name = name.split("(")[0].strip('"')
    for etc in etc_dirs(env):
        top = os.path.join(etc, "caseDicts", "postProcessing")
        for root, _dirs, files in os.walk(top):
            if name in files:
                return os.path.join(root, name)
    return None


def uses_unsupported(path, case, env, seen=None):
    """Name of the file (path or an included file) using #calc, #codeStream
    or a verbatim #{ #} block, or None."""
    if seen is None:
        seen = set()
    if path in seen or len(seen) > 200:
        return None
    seen.add(path)
    try:
        with open(path, "r", encoding="utf-8", errors="replace") as h:
            text = strip_comments(h.read())
    except OSError:
        return None
    if UNSUPPORTED_RE.search(text):
        return path
    for m in INCLUDE_RE.finditer(text):
        kind, arg = m.group(1), m.group(2).strip('"')
        arg = arg.replace("${FOAM_CASE}", case).replace("$FOAM_CASE", case)
        if kind in ("includeEtc", "sincludeEtc"):
            cands = [os.path.join(e, arg) for e in etc_dirs(env)]
        elif kind == "includeFunc":
            f = find_function_object(arg, env)
            cands = [f] if f else []
        else:
            cands = [arg if os.path.isabs(arg)
                     else os.path.join(os.path.dirname(path), arg)]
        for c in cands:
            if c and os.path.isfile(c):
                hit = uses_unsupported(os.path.normpath(c), case, env, seen)
                if hit:
                    return hit
    return None


# ---------------------------------------------------------------------------
# FoamFile parser (for canonical -expand output: no macros, no directives)
# ---------------------------------------------------------------------------

class ParseError(Exception):
    pass


class Num:
    __slots__ = ("v", "text")

    def __init__(self, v, text):
        self.v = v
        self.text = text

    def is_int(self):
        return re.fullmatch(r"-?\d+", self.text) is not None


class Text:
    """A word (quoted False) or a string (quoted True)."""
    __slots__ = ("s", "quoted")

    def __init__(self, s, quoted):
        self.s = s
        self.quoted = quoted


class Punct:
    __slots__ = ("c",)

    def __init__(self, c):
        self.c = c


class Verbatim:
    __slots__ = ("s",)

    def __init__(self, s):
        self.s = s


class Group:
    """( ... ) or [ ... ] group of items."""
    __slots__ = ("kind", "items")

    def __init__(self, kind, items):
        self.kind = kind
        self.items = items


class Uniform:
    """N{v}: n copies of item v."""
    __slots__ = ("n", "item")

    def __init__(self, n, item):
        self.n = n
        self.item = item


class Dict:
    __slots__ = ("entries", "quoted", "duplicates")

    def __init__(self):
        self.entries = {}     # key text -> Dict or list of items
        self.quoted = {}      # key text -> bool
        self.duplicates = []


NUM_RE = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
                    r"(?=[\s;{}()\[\]/\"]|\Z)")
WORD_RE = re.compile(r"(?=([^\s\"'/;{}()\[\]]+))\1(?![(])")  # atomic
WS_RE = re.compile(r"(?:\s+|//[^\n]*|/\*.*?\*/)+", re.S)
STRING_RE = re.compile(r'"((?:[^"\\]|\\.)*)"', re.S)
VERBATIM_RE = re.compile(r"#\{(.*?)#\}", re.S)
WORD_STOP = set(" \t\n\r\f\v\"'/;{}")
PUNCT = set(";{}()[],:=+*/^&|<>!?-")


def decode_string(raw):
    # As ISstream::read(string&): backslash-quote is a quote, an escaped
    # newline is kept as a newline, any other backslash stays.
    return raw.replace("\\\n", "\n").replace('\\"', '"')


def tokenize(text, offsets=None):
    """Tokens of text; the start offset of each is appended to offsets."""
    toks = []
    append = toks.append
    i, n = 0, len(text)
    while i < n:
        m = WS_RE.match(text, i)
        if m:
            i = m.end()
            if i >= n:
                break
        if offsets is not None:
            offsets.append(i)
        c = text[i]
        if c == '"':
            m = STRING_RE.match(text, i)
            if not m:
                raise ParseError("unterminated string at offset %d" % i)
            append(Text(decode_string(m.group(1)), True))
            i = m.end()
            continue
        if c == "#" and text.startswith("#{", i):
            m = VERBATIM_RE.match(text, i)
            if not m:
                raise ParseError("unterminated #{ at offset %d" % i)
            append(Verbatim(m.group(1).strip()))
            i = m.end()
            continue
        if c in "-+.0123456789":
            m = NUM_RE.match(text, i)
            if m:
                t = m.group(0)
                append(Num(float(t), t))
                i = m.end()
                continue
        if c in "{}()[];":
            append(Punct(c))
            i += 1
            continue
        if c == "/":
            append(Punct(c))
            i += 1
            continue
        m = WORD_RE.match(text, i)
        if m:
            append(Text(m.group(0), False))
            i = m.end()
            continue
        # a word with ( ) inside, e.g. div(phi,U): OpenFOAM's word rule
        j, depth = i, 0
        while j < n:
            ch = text[j]
            if ch in WORD_STOP or ch.isspace():
                break
            if ch == "(":
                depth += 1
            elif ch == ")":
                if depth == 0:
                    break
                depth -= 1
            elif ch in "[]" and depth == 0:
                break
            j += 1
        if j == i:
            append(Punct(c))
            i += 1
        else:
            append(Text(text[i:j], False))
            i = j
    return toks


class Parser:
    def __init__(self, toks):
        self.toks = toks
        self.pos = 0

    def peek(self):
        return self.toks[self.pos] if self.pos < len(self.toks) else None

    def next(self):
        t = self.peek()
        self.pos += 1
        return t

    def parse_top(self):
        d = self.parse_dict_body(top=True)
        return d

    def parse_dict_body(self, top):
        d = Dict()
        while True:
            t = self.next()
            if t is None:
                if top:
                    return d
                raise ParseError("unexpected end of input inside { }")
            if isinstance(t, Punct):
                if t.c == "}" and not top:
                    return d
                if t.c == ";":
                    continue
                raise ParseError("unexpected '%s' where a keyword was expected"
                                 % t.c)
            if isinstance(t, Text):
                key, quoted = t.s, t.quoted
            elif isinstance(t, Num):
                key, quoted = t.text, False
            else:
                raise ParseError("unexpected verbatim block as keyword")
            nxt = self.peek()
            if isinstance(nxt, Punct) and nxt.c == "{":
                self.next()
                value = self.parse_dict_body(top=False)
            else:
                value = self.parse_items(";")
            if key in d.entries:
                d.duplicates.append(key)
            else:
                d.quoted[key] = quoted
            d.entries[key] = value

    def parse_items(self, end):
        """Items up to the closing `end` punctuation (consumed)."""
        items = []
        while True:
            t = self.next()
            if t is None:
                if end == ";":
                    return normalise(items)  # tolerate a missing final ';'
                raise ParseError("unexpected end of input, expected '%s'" % end)
            if isinstance(t, Punct):
                c = t.c
                if c == end:
                    return normalise(items)
                if c == "(":
                    items.append(Group("(", self.parse_items(")")))
                    continue
                if c == "[":
                    items.append(Group("[", self.parse_items("]")))
                    continue
                if c == "{":
                    items.append(self.parse_brace(items))
                    continue
                if c in ")]}" or (c == ";" and end != ";"):
                    if c == ";" and end in ")]":
                        # a ';' inside a list: part of the token stream
                        items.append(t)
                        continue
                    raise ParseError("unbalanced '%s' (expected '%s')"
                                     % (c, end))
            items.append(t)

    def parse_brace(self, items):
        """{ inside a primitive entry: uniform list N{v} or a dictionary."""
        if items and isinstance(items[-1], Num) and items[-1].is_int() \
                and items[-1].v >= 0:
            save = self.pos
            try:
                one = self.parse_items("}")
                if len(one) == 1 and not isinstance(one[0], Dict):
                    n = items.pop()
                    return Uniform(int(n.v), one[0])
            except ParseError:
                pass
            self.pos = save
        return self.parse_dict_body(top=False)


def list_count(items):
    """Element count of a list; `name { ... }` pairs count as one."""
    n, i = 0, 0
    while i < len(items):
        if (isinstance(items[i], (Text, Num)) and i + 1 < len(items)
                and isinstance(items[i + 1], Dict)):
            i += 2
        else:
            i += 1
        n += 1
    return n


def normalise(items):
    """Drop the size of sized lists N( ... ) whose size matches."""
    out = []
    for it in items:
        if (isinstance(it, Group) and it.kind == "(" and out
                and isinstance(out[-1], Num) and out[-1].is_int()):
            n = int(out[-1].v)
            if n == len(it.items) or n == list_count(it.items):
                out.pop()
        out.append(it)
    return out


BANNER_RE = re.compile(r"^/\*-+\*- C\+\+ -\*-+\*\\\s*$", re.M)
WARNING_RE = re.compile(r"^--> FOAM Warning :.*?(?=^\S|\Z)", re.M | re.S)


def split_warnings(text):
    """(dictionary text, [warnings]): OpenFOAM prints warnings on stdout,
    before the banner that starts the written dictionary."""
    warnings = [" ".join(w.split()) for w in WARNING_RE.findall(text)]
    m = BANNER_RE.search(text)
    if m:
        text = text[m.start():]
    elif warnings:
        text = WARNING_RE.sub("", text)
    return text, warnings


def parse_foam(text):
    text = split_warnings(text)[0]
    offsets = []
    parser = Parser(tokenize(text, offsets))
    try:
        return parser.parse_top()
    except ParseError as e:
        k = min(max(parser.pos - 1, 0), len(offsets) - 1)
        if k < 0:
            raise
        off = offsets[k]
        line = text.count("\n", 0, off) + 1
        start = text.rfind("\n", 0, off) + 1
        end = text.find("\n", off)
        src = text[start:end if end >= 0 else len(text)]
        col = off - start
        lo = max(0, col - 60)
        raise ParseError("%s, output line %d: %s<<HERE>>%s" % (
            e, line, src[lo:col], src[col:col + 40]))


def quote(s):
    """As OSstream::writeQuoted: escape quotes and newlines."""
    return '"%s"' % s.replace('"', '\\"').replace("\n", "\\\n")


def write_foam(d, indent=0):
    """FoamFile text of a parsed tree (used by --self-compare)."""
    pad = "    " * indent
    lines = []
    for k, v in d.entries.items():
        key = quote(k) if d.quoted.get(k) else k
        if isinstance(v, Dict):
            lines.append("%s%s\n%s{\n%s%s}" % (pad, key, pad,
                                               write_foam(v, indent + 1), pad))
        else:
            lines.append("%s%s %s;" % (pad, key, write_items(v)))
    return "".join(l + "\n" for l in lines)


def write_items(items):
    return " ".join(write_item(it) for it in items)


def write_item(it):
    if isinstance(it, Num):
        return it.text
    if isinstance(it, Text):
        return quote(it.s) if it.quoted else it.s
    if isinstance(it, Punct):
        return it.c
    if isinstance(it, Verbatim):
        return "#{ %s #}" % it.s
    if isinstance(it, Uniform):
        return "%d{%s}" % (it.n, write_item(it.item))
    if isinstance(it, Group):
        return "%s %s %s" % (it.kind, write_items(it.items),
                             ")" if it.kind == "(" else "]")
    if isinstance(it, Dict):
        return "{ %s }" % write_foam(it).replace("\n", " ")
    raise TypeError(it)


# ---------------------------------------------------------------------------
# Comparison
# ---------------------------------------------------------------------------

IGNORED_HEADER_KEYS = {"note", "location"}


class Cmp:
    def __init__(self, rtol, atol, strict_quotes, max_diffs=50):
        self.rtol = rtol
        self.atol = atol
        self.strict_quotes = strict_quotes
        self.diffs = []   # (path, foam text, nmm text, what)
        self.notes = []
        self.max_diffs = max_diffs

    def diff(self, path, a, b, what):
        if len(self.diffs) < self.max_diffs:
            self.diffs.append((path or "<top>", render(a), render(b), what))

    def note(self, msg):
        if len(self.notes) < 20:
            self.notes.append(msg)

    def compare_top(self, fa, fb):
        for d, who in ((fa, "foam"), (fb, "nmm")):
            for k in d.duplicates:
                self.diff(k, "", "", "duplicate keyword in %s output" % who)
        ha = fa.entries.get("FoamFile")
        hb = fb.entries.get("FoamFile")
        if isinstance(ha, Dict) and isinstance(hb, Dict):
            for h in (ha, hb):
                for k in IGNORED_HEADER_KEYS:
                    h.entries.pop(k, None)
            self.compare_dict(ha, hb, "FoamFile")
        for d in (fa, fb):
            d.entries.pop("FoamFile", None)
        self.compare_dict(fa, fb, "")

    def compare_dict(self, a, b, path):
        pre = path + "/" if path else ""
        ka = list(a.entries)
        kb = list(b.entries)
        sb = set(kb)
        sa = set(ka)
        for k in ka:
            if k not in sb:
                self.diff(pre + k, a.entries[k], MISSING, "keyword missing in nmm")
        for k in kb:
            if k not in sa:
                self.diff(pre + k, MISSING, b.entries[k], "extra keyword in nmm")
        common_a = [k for k in ka if k in sb]
        common_b = [k for k in kb if k in sa]
        if common_a != common_b:
            self.note("%s: keyword order differs" % (path or "<top>"))
        for k in common_a:
            qa, qb = a.quoted.get(k), b.quoted.get(k)
            if qa != qb:
                msg = "%s: keyword quoted in %s only" % (
                    pre + k, "foam" if qa else "nmm")
                if self.strict_quotes:
                    self.diff(pre + k, k, k, msg)
                else:
                    self.note(msg)
            self.compare_value(a.entries[k], b.entries[k], pre + k)

    def compare_value(self, va, vb, path):
        if isinstance(va, Dict) and isinstance(vb, Dict):
            self.compare_dict(va, vb, path)
        elif isinstance(va, Dict) or isinstance(vb, Dict):
            self.diff(path, va, vb, "dictionary vs primitive entry")
        else:
            self.compare_items(va, vb, path, va, vb)

    def compare_items(self, ia, ib, path, whole_a, whole_b):
        if len(ia) != len(ib):
            self.diff(path, whole_a, whole_b,
                      "token count differs (%d vs %d)" % (len(ia), len(ib)))
            return
        for k, (x, y) in enumerate(zip(ia, ib)):
            sub = path if len(ia) == 1 else "%s[%d]" % (path, k)
            if not self.compare_item(x, y, sub):
                return

    def compare_item(self, x, y, path):
        """True when equal (notes may be recorded); records a diff if not."""
        if isinstance(x, Uniform) or isinstance(y, Uniform):
            ea, eb = expand_list(x), expand_list(y)
            if ea is None or eb is None:
                self.diff(path, x, y, "uniform list vs other")
                return False
            na, nb = list_len(x), list_len(y)
            if na != nb:
                self.diff(path, x, y, "list size differs (%d vs %d)" % (na, nb))
                return False
            for k in range(na):
                if not self.compare_item(ea(k), eb(k), "%s[%d]" % (path, k)):
                    return False
            return True
        if type(x) is not type(y):
            self.diff(path, x, y, "different kind of token")
            return False
        if isinstance(x, Num):
            if x.v == y.v or math.isclose(x.v, y.v, rel_tol=self.rtol,
                                          abs_tol=self.atol):
                return True
            self.diff(path, x, y, "numbers differ")
            return False
        if isinstance(x, Text):
            if x.s != y.s:
                self.diff(path, x, y, "text differs")
                return False
            if x.quoted != y.quoted:
                msg = "%s: %r quoted in %s only" % (
                    path, x.s, "foam" if x.quoted else "nmm")
                if self.strict_quotes:
                    self.diff(path, x, y, "quoting differs")
                    return False
                self.note(msg)
            return True
        if isinstance(x, Punct):
            if x.c != y.c:
                self.diff(path, x, y, "punctuation differs")
                return False
            return True
        if isinstance(x, Verbatim):
            if x.s != y.s:
                self.diff(path, x, y, "verbatim text differs")
                return False
            return True
        if isinstance(x, Group):
            if x.kind != y.kind:
                self.diff(path, x, y, "different bracket")
                return False
            before = len(self.diffs)
            self.compare_items(x.items, y.items, path, x, y)
            return len(self.diffs) == before
        if isinstance(x, Dict):
            before = len(self.diffs)
            self.compare_dict(x, y, path)
            return len(self.diffs) == before
        self.diff(path, x, y, "unknown token")
        return False


def list_len(x):
    return x.n if isinstance(x, Uniform) else len(x.items)


def expand_list(x):
    if isinstance(x, Uniform):
        return lambda k: x.item
    if isinstance(x, Group) and x.kind == "(":
        return lambda k: x.items[k]
    return None


class _Missing:
    pass


MISSING = _Missing()


def render(v, limit=160):
    out = []
    _render(v, out)
    s = " ".join(out)
    return s if len(s) <= limit else s[:limit - 3] + "..."


def _render(v, out):
    if len(out) > 80:
        return
    if v is MISSING:
        out.append("<missing>")
    elif isinstance(v, str):
        out.append(v)
    elif isinstance(v, list):
        for it in v:
            _render(it, out)
    elif isinstance(v, Num):
        out.append(v.text)
    elif isinstance(v, Text):
        t = quote(v.s) if v.quoted else v.s
        out.append(t.replace("\\\n", "\\n").replace("\t", "\\t"))
    elif isinstance(v, Punct):
        out.append(v.c)
    elif isinstance(v, Verbatim):
        out.append("#{ %s #}" % v.s)
    elif isinstance(v, Uniform):
        out.append("%d{" % v.n)
        _render(v.item, out)
        out.append("}")
    elif isinstance(v, Group):
        out.append(v.kind)
        _render(v.items, out)
        out.append(")" if v.kind == "(" else "]")
    elif isinstance(v, Dict):
        out.append("{")
        for k, val in v.entries.items():
            out.append(k)
            _render(val, out)
            if not isinstance(val, Dict):
                out.append(";")
        out.append("}")


def compare_texts(foam_text, nmm_text, rtol=1e-5, atol=0.0,
                  strict_quotes=False):
    """Parse and compare two -expand outputs: (diffs, notes)."""
    cmp = Cmp(rtol, atol, strict_quotes)
    cmp.compare_top(parse_foam(foam_text), parse_foam(nmm_text))
    return cmp.diffs, cmp.notes


# ---------------------------------------------------------------------------
# Running the readers
# ---------------------------------------------------------------------------

CFG = {}


def init_worker(cfg):
    CFG.update(cfg)


def run_reader(cmd, cwd, env):
    t0 = time.monotonic()
    env = dict(env)
    env["PWD"] = cwd  # as a shell sets it (else OpenFOAM warns on stdout)
    try:
        p = subprocess.run(cmd, cwd=cwd, env=env, stdin=subprocess.DEVNULL,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           timeout=CALL_TIMEOUT)
        out = p.stdout.decode("utf-8", errors="replace")
        err = p.stderr.decode("utf-8", errors="replace")
        rc = p.returncode
    except subprocess.TimeoutExpired:
        out, err, rc = "", "timeout after %ds" % CALL_TIMEOUT, -999
    except OSError as e:
        out, err, rc = "", "cannot run %s: %s" % (cmd[0], e), -998
    return rc, out, err, time.monotonic() - t0


def first_error(out, err, limit=3):
    text = err + "\n" + out
    lines = [l.strip() for l in text.splitlines()]
    for i, l in enumerate(lines):
        if "FATAL" in l or l.startswith("timeout") or l.startswith("cannot run"):
            rest = [x for x in lines[i + 1:] if x][:limit]
            return " | ".join([l] + rest)
    rest = [x for x in lines if x][:limit]
    return " | ".join(rest) or "(no message)"


def failed(rc, out, err):
    return rc != 0 or "FOAM FATAL" in out or "FOAM FATAL" in err \
        or "FATAL ERROR" in err


def check_file(task):
    path, case = task
    cfg = CFG
    rel = os.path.relpath(path, case)
    if rel.startswith("-"):
        rel = os.path.join(".", rel)  # e.g. time directory -180: not an option
    res = {"path": path, "case": case, "rel": rel, "foam_time": 0.0,
           "nmm_time": 0.0, "diffs": [], "notes": [], "msg": ""}
    hit = uses_unsupported(path, case, cfg["env"])
    if hit:
        res["status"] = "skipped-unsupported"
        res["msg"] = ("#calc/#codeStream/#{ in %s" % os.path.relpath(hit, case)
                      if hit != path else "#calc/#codeStream/#{")
        return res
    rc, fout, ferr, dt = run_reader(
        [cfg["foam"], "-precision", str(cfg["precision"]), "-expand", rel],
        case, cfg["env"])
    res["foam_time"] = dt
    if failed(rc, fout, ferr):
        res["status"] = "skipped-foam-rejects"
        res["msg"] = first_error(fout, ferr)
        return res
    res["foam_warnings"] = [w[:300] for w in split_warnings(fout)[1][:5]]
    try:
        ftree = parse_foam(fout)
    except ParseError as e:
        res["status"] = "harness-error"
        res["msg"] = "cannot parse foamDictionary output: %s" % e
        save_outputs(cfg, res, fout, None)
        return res
    if cfg["self_compare"]:
        # Round trip: our own rendering of the parsed reference, read back
        # by foamDictionary, must agree with the reference.
        with tempfile.TemporaryDirectory(prefix="foamRoundTrip.") as tdir:
            with open(os.path.join(tdir, "dict"), "w") as h:
                h.write(write_foam(ftree))
            rc, nout, nerr, dt = run_reader(
                [cfg["foam"], "-precision", str(cfg["precision"]), "-expand",
                 "dict"], tdir, cfg["env"])
        res["nmm_time"] = dt
        if failed(rc, nout, nerr):
            res["status"] = "nmm-error"
            res["msg"] = "round trip rejected by foamDictionary: %s" % (
                first_error(nout, nerr))
            save_outputs(cfg, res, fout, write_foam(ftree))
            return res
    else:
        rc, nout, nerr, dt = run_reader([cfg["nmm"], "-expand", rel], case,
                                        cfg["nmm_env"])
        res["nmm_time"] = dt
        if failed(rc, nout, nerr):
            res["status"] = "nmm-error"
            res["msg"] = "nmmDictionary failed (rc=%d): %s" % (
                rc, first_error(nout, nerr))
            save_outputs(cfg, res, fout, nout + "\n// stderr:\n" + nerr)
            return res
    try:
        ntree = parse_foam(nout)
    except ParseError as e:
        res["status"] = "nmm-error"
        res["msg"] = "cannot parse nmmDictionary output: %s" % e
        save_outputs(cfg, res, fout, nout)
        return res
    cmp = Cmp(cfg["rtol"], cfg["atol"], cfg["strict_quotes"])
    cmp.compare_top(ftree, ntree)
    res["diffs"] = cmp.diffs
    res["notes"] = ["foamDictionary warned: " + w
                    for w in res["foam_warnings"]] + cmp.notes
    res["status"] = "disagreed" if cmp.diffs else "agreed"
    if cmp.diffs:
        save_outputs(cfg, res, fout, nout)
    return res


def save_outputs(cfg, res, fout, nout):
    d = cfg.get("save")
    if not d:
        return
    name = os.path.relpath(res["path"], cfg["display_root"]) \
        if cfg["display_root"] else res["path"].lstrip(os.sep)
    base = os.path.join(d, name.replace(os.sep, "__"))
    os.makedirs(d, exist_ok=True)
    with open(base + ".foam", "w") as h:
        h.write(fout)
    if nout is not None:
        with open(base + ".nmm", "w") as h:
            h.write(nout)


# ---------------------------------------------------------------------------
# Self test of the comparator (it must be able to fail)
# ---------------------------------------------------------------------------

SELFTEST_BASE = r"""
/* banner */
// "system/x"
FoamFile { version 2; format ascii; class dictionary; location "system"; object x; }
a 1;
b 0.5;
s "text \"q\"";
w word;
div(phi,U) Gauss linear;
l ( 1 2 3 );
sl 3 ( 1 2 3 );
u 3 { 1.5 };
v nonuniform List<vector> 2 ( ( 1 2 3 ) ( 4 5 6 ) );
dim [ 0 2 -1 0 0 0 0 ] 1e-05;
sub { x 1; y { z ( a b ); } }
"(U|k).*" 5;
boundary ( inlet { type patch; faces ( ( 0 1 2 3 ) ); } outlet { type patch; } );
empty ( );
e ;
"""


def selftest():
    base = SELFTEST_BASE
    same = [
        ("identical", base),
        ("keyword order", base.replace("a 1;\nb 0.5;", "b 0.5;\na 1;")),
        ("integer vs float", base.replace("a 1;", "a 1.0;")),
        ("exponent form", base.replace("b 0.5;", "b 5e-1;")),
        ("6 digits", base.replace("b 0.5;", "b 0.5000001;")),
        ("size dropped", base.replace("sl 3 (", "sl (")),
        ("size added", base.replace("l ( 1 2 3 )", "l 3(1 2 3)")),
        ("uniform expanded", base.replace("u 3 { 1.5 }", "u (1.5 1.5 1.5)")),
        ("word vs string", base.replace("w word;", 'w "word";')),
        ("spacing", base.replace("( ( 1 2 3 ) ( 4 5 6 ) )",
                                 "((1 2 3)(4 5 6))")),
        ("list of dicts sized", base.replace("boundary (", "boundary 2(")),
        ("header location", base.replace('location "system";', "")),
        ("header version", base.replace("version 2;", "version 2.0;")),
        ("comments", base.replace("a 1;", "a /* c */ 1; // x")),
    ]
    differ = [
        ("wrong number", base.replace("b 0.5;", "b 0.51;")),
        ("missing key", base.replace("a 1;", "")),
        ("extra key", base + "extra 1;\n"),
        ("missing nested key", base.replace("x 1;", "")),
        ("dict vs primitive", base.replace("sub { x 1; y { z ( a b ); } }",
                                           "sub 1;")),
        ("wrong word", base.replace("w word;", "w other;")),
        ("string text", base.replace(r'\"q\"', "q")),
        ("list length", base.replace("l ( 1 2 3 )", "l ( 1 2 )")),
        ("uniform size", base.replace("u 3 { 1.5 }", "u 2 { 1.5 }")),
        ("uniform value", base.replace("u 3 { 1.5 }", "u (1.5 1.5 1.6)")),
        ("size mismatch kept", base.replace("sl 3 (", "sl 4 (")),
        ("vector component", base.replace("( 4 5 6 )", "( 4 5 7 )")),
        ("dims", base.replace("[ 0 2 -1", "[ 0 2 -2")),
        ("nested list", base.replace("z ( a b )", "z ( a ( b ) )")),
        ("header class", base.replace("class dictionary", "class volScalarField")),
        ("list dict entry", base.replace("type patch; faces", "type wall; faces")),
        ("duplicate", base + "a 1;\n"),
        ("function name", base.replace("div(phi,U)", "div(phi,V)")),
        ("empty vs value", base.replace("e ;", "e 0;")),
    ]
    bad = 0
    for name, text in same:
        diffs, _ = compare_texts(base, text)
        if diffs:
            bad += 1
            print("SELFTEST FAIL (should agree): %s: %s" % (name, diffs[:2]))
    for name, text in differ:
        diffs, _ = compare_texts(base, text)
        if not diffs:
            bad += 1
            print("SELFTEST FAIL (should disagree): %s" % name)
    diffs, _ = compare_texts(base, base.replace("w word;", 'w "word";'),
                             strict_quotes=True)
    if not diffs:
        bad += 1
        print("SELFTEST FAIL: --strict-quotes accepted a quoting difference")
    try:
        parse_foam("a { b 1;")
        bad += 1
        print("SELFTEST FAIL: unbalanced input parsed")
    except ParseError:
        pass
    total = len(same) + len(differ) + 1
    print("%d passed, %d failed" % (total - bad, bad))
    return 1 if bad else 0


# ---------------------------------------------------------------------------
# Reporting
# ---------------------------------------------------------------------------

def main(argv=None):
    ap = argparse.ArgumentParser(
        description="Compare nmmDictionary -expand with OpenFOAM's "
                    "foamDictionary -expand.",
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("files", nargs="*", help="explicit files (or directories)")
    ap.add_argument("--examples", action="store_true",
                    help="OpenFOAM's examples (openfoam-examples package)")
    ap.add_argument("--examples-root", default=None,
                    help="source of --examples (default %s)" % DEFAULT_EXAMPLES)
    ap.add_argument("--tree", nargs="+", metavar="DIR",
                    help="every dictionary of the cases below DIR")
    ap.add_argument("--nmm", metavar="PATH", help="nmmDictionary executable")
    ap.add_argument("--self-compare", action="store_true",
                    help="instead of nmmDictionary, re-read this script's own "
                         "rendering of foamDictionary's output with "
                         "foamDictionary (tests the parser and comparator on "
                         "real data without nmmDictionary)")
    ap.add_argument("--selftest", action="store_true",
                    help="run the comparator's built-in checks and exit")
    ap.add_argument("--jobs", "-j", type=int, default=0,
                    help="parallel workers (default: cores, 2..4)")
    ap.add_argument("--limit", type=int, default=0,
                    help="only the first N files")
    ap.add_argument("--list-failures", action="store_true",
                    help="print every disagreement in full and every "
                         "skipped/excluded file")
    ap.add_argument("--keep-going", action="store_true",
                    help="go on after the first disagreement (default: stop "
                         "scheduling new files)")
    ap.add_argument("--foam-precision", type=int, default=FOAM_PRECISION,
                    help="foamDictionary -precision (default %d)"
                    % FOAM_PRECISION)
    ap.add_argument("--rtol", type=float, default=1e-5)
    ap.add_argument("--atol", type=float, default=0.0)
    ap.add_argument("--strict-quotes", action="store_true",
                    help="a word vs a quoted string with the same text is a "
                         "disagreement")
    ap.add_argument("--notes", action="store_true",
                    help="print the notes (order/quoting differences)")
    ap.add_argument("--bashrc", default=DEFAULT_BASHRC)
    ap.add_argument("--work-dir", help="where --examples is materialised "
                    "(kept; default: a temporary directory removed at exit)")
    ap.add_argument("--save", metavar="DIR",
                    help="write both outputs of every failing file to DIR")
    ap.add_argument("--max-diffs", type=int, default=5,
                    help="differences printed per file (default 5)")
    args = ap.parse_args(argv)

    if args.selftest:
        return selftest()
    if not (args.examples or args.tree or args.files):
        ap.error("nothing to check: give --examples, --tree DIR or files")
    if not args.nmm and not args.self_compare:
        ap.error("--nmm PATH is required (or --self-compare)")
    if args.nmm and not (os.path.isfile(args.nmm)
                         and os.access(args.nmm, os.X_OK)):
        die("nmmDictionary not found or not executable: %s" % args.nmm)

    t_start = time.monotonic()
    env, foam = foam_environment(args.bashrc)
    if args.save:
        reset_dir(args.save)  # only the failures of this run
    coll = Collection()
    tmp = None
    display_root = None
    if args.examples:
        src = args.examples_root or DEFAULT_EXAMPLES
        if args.work_dir:
            dst = os.path.abspath(args.work_dir)
            reset_dir(dst)
        else:
            tmp = tempfile.mkdtemp(prefix="foamConformance.")
            dst = os.path.join(tmp, "examples")
        t0 = time.monotonic()
        materialise_examples(src, dst, coll)
        coll.notes.append("materialising took %.1f s" % (time.monotonic() - t0))
        args.examples_root = dst
        display_root = dst
    try:
        collect(args, coll)
        files = coll.files
        if args.limit:
            files = files[:args.limit]
        jobs = args.jobs or max(2, min(4, os.cpu_count() or 2))
        nmm_env = dict(env)
        cfg = {"env": env, "nmm_env": nmm_env, "foam": foam,
               "nmm": os.path.abspath(args.nmm) if args.nmm else None,
               "self_compare": args.self_compare, "rtol": args.rtol,
               "precision": args.foam_precision,
               "atol": args.atol, "strict_quotes": args.strict_quotes,
               "save": os.path.abspath(args.save) if args.save else None,
               "display_root": display_root}
        results = run_all(files, cfg, jobs, args.keep_going)
        return report(args, coll, files, results, jobs, display_root,
                      time.monotonic() - t_start)
    finally:
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)


MARKER = ".foamConformance"


def reset_dir(path):
    """Empty a directory this script made before (never anything else)."""
    if os.path.isdir(path) and os.listdir(path):
        if not os.path.exists(os.path.join(path, MARKER)):
            die("%s exists and was not made by this script: not touching it"
                % path)
        shutil.rmtree(path)
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, MARKER), "w") as h:
        h.write("scratch directory of foamConformance.py\n")


def run_all(files, cfg, jobs, keep_going):
    results = []
    if not files:
        return results
    with concurrent.futures.ProcessPoolExecutor(
            max_workers=jobs, initializer=init_worker,
            initargs=(cfg,)) as pool:
        pending = set()
        it = iter(files)
        stop = False

        def refill():
            while not stop and len(pending) < jobs * 4:
                try:
                    t = next(it)
                except StopIteration:
                    return
                pending.add(pool.submit(check_file, t))

        refill()
        while pending:
            done, _ = concurrent.futures.wait(
                pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for f in done:
                pending.discard(f)
                r = f.result()
                results.append(r)
                if r["status"] in FAIL_STATES and not keep_going:
                    stop = True
            refill()
    order = {p: i for i, (p, _c) in enumerate(files)}
    results.sort(key=lambda r: order[r["path"]])
    return results


FAIL_STATES = ("disagreed", "nmm-error", "harness-error")


def report(args, coll, files, results, jobs, display_root, wall):
    def name(p):
        if not os.path.isabs(p):
            return p
        if display_root and p.startswith(display_root + os.sep):
            return os.path.relpath(p, display_root)
        cwd = os.getcwd()
        return os.path.relpath(p, cwd) if p.startswith(cwd + os.sep) else p

    by = {}
    for r in results:
        by.setdefault(r["status"], []).append(r)
    out = sys.stdout.write
    for note in coll.notes:
        out("note: %s\n" % note)
    n_exc = sum(len(v) for v in coll.excluded.values())
    out("\nexcluded %d files before running anything:\n" % n_exc)
    for reason in sorted(coll.excluded):
        paths = coll.excluded[reason]
        out("  %-45s %5d\n" % (reason, len(paths)))
        if args.list_failures:
            for p in paths:
                out("      %s\n" % name(p))

    fails = [r for r in results if r["status"] in FAIL_STATES]
    limit = None if args.list_failures else 20
    if fails:
        out("\nDISAGREEMENTS (%d):\n" % len(fails))
        for i, r in enumerate(fails):
            if limit is not None and i >= limit:
                out("  ... and %d more (use --list-failures):\n" % (len(fails) - limit))
                for rr in fails[limit:]:
                    out("      %s  [%s]\n" % (name(rr["path"]), rr["status"]))
                break
            out("\n  %s  [%s]\n" % (name(r["path"]), r["status"]))
            if r["msg"]:
                out("      %s\n" % r["msg"])
            for path, fa, nb, what in r["diffs"][:args.max_diffs]:
                out("      %s: %s\n" % (path, what))
                out("          foam: %s\n" % fa)
                out("          nmm : %s\n" % nb)
            if len(r["diffs"]) > args.max_diffs:
                out("      ... %d%s more differences\n" % (
                    len(r["diffs"]) - args.max_diffs,
                    "+" if len(r["diffs"]) >= 50 else ""))

    for status in ("skipped-foam-rejects", "skipped-unsupported"):
        lst = by.get(status, [])
        if lst:
            out("\n%s (%d):\n" % (status, len(lst)))
            for r in lst:
                out("  %s: %s\n" % (name(r["path"]), r["msg"][:200]))

    if args.notes:
        noted = [r for r in results if r["notes"]]
        if noted:
            out("\nnotes (%d files):\n" % len(noted))
            for r in noted:
                out("  %s\n" % name(r["path"]))
                for n in r["notes"][:5]:
                    out("      %s\n" % n)

    n_agreed = len(by.get("agreed", []))
    n_skipped = len(by.get("skipped-foam-rejects", [])) + \
        len(by.get("skipped-unsupported", []))
    n_dis = len(fails)
    not_run = len(files) - len(results)
    foam_t = [r["foam_time"] for r in results if r["foam_time"]]
    nmm_t = [r["nmm_time"] for r in results if r["nmm_time"]]
    out("\nfiles: %d checked of %d candidates (%d excluded)%s\n" % (
        len(results), len(files), n_exc,
        ", %d not run after the first failure (use --keep-going)" % not_run
        if not_run else ""))
    out("  agreed               %d\n" % n_agreed)
    out("  skipped-foam-rejects %d\n" % len(by.get("skipped-foam-rejects", [])))
    out("  skipped-unsupported  %d\n" % len(by.get("skipped-unsupported", [])))
    out("  disagreed            %d\n" % len(by.get("disagreed", [])))
    out("  nmm-error            %d\n" % len(by.get("nmm-error", [])))
    if by.get("harness-error"):
        out("  harness-error        %d\n" % len(by["harness-error"]))
    n_notes = sum(1 for r in results if r["notes"])
    if n_notes:
        out("  (%d agreeing or disagreeing files have notes: --notes)\n"
            % n_notes)
    if foam_t:
        out("foamDictionary: %d calls, %.1f s total, %.0f ms per file\n" % (
            len(foam_t), sum(foam_t), 1000 * sum(foam_t) / len(foam_t)))
    if nmm_t:
        out("nmmDictionary:  %d calls, %.1f s total, %.0f ms per file\n" % (
            len(nmm_t), sum(nmm_t), 1000 * sum(nmm_t) / len(nmm_t)))
    out("wall time %.1f s with %d workers\n" % (wall, jobs))
    out("conformance: %d agreed / %d skipped / %d disagreed\n"
        % (n_agreed, n_skipped, n_dis))
    sys.stdout.flush()
    return 1 if n_dis else 0


if __name__ == "__main__":
    sys.exit(main())
