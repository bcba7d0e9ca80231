#!/usr/bin/env python3
"""
Description
    Checks that the top-level folders of src/nmmSolid form the layers that
    src/nmmSolid/layers declares (the order is stated there only, beside
    the folders it orders, so that whoever adds a folder finds it):

      (a) a folder includes no header of a folder listed after it;
      (b) no two top-level folders include each other, directly or through
          others (this also catches folders missing from the list);
      (c) every top-level folder, and every folder an include names, is in
          the list.

    It reads every .H, .C and .H.in file below the library folder and takes
    each '#include "nmmSolid/<folder>/..."' outside comments. The included
    file need not exist in the source tree: nmmSolid/global/version.H is
    generated in the build tree, and is in global like any other header.

    Each failure names the file, the line and the include; the exit code is
    1 when there is any, 0 otherwise.

Usage
    checkLayers.py <src/nmmSolid> [<layers file, default src/nmmSolid/layers>]
"""

import os
import re
import sys

SOURCE_SUFFIXES = (".H", ".C", ".H.in")

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]nmmSolid/([^">]*)[">]')


def readLayers(fileName):
    """The folder names in order, each with its line; '#' starts a comment"""
    layers = []
    errors = []
    with open(fileName, encoding="utf-8") as f:
        for lineNo, line in enumerate(f, 1):
            name = line.split("#", 1)[0].strip()
            if not name:
                continue
            if any(name == n for n, _ in layers):
                errors.append(f"{fileName}:{lineNo}: '{name}' is listed twice")
                continue
            layers.append((name, lineNo))
    return [n for n, _ in layers], errors


def withoutComments(text):
    """The text with comments blanked out, keeping lines and columns, so
    that an include in a Usage block or a commented-out one is no
    dependency"""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            # A literal: skip to its closing quote (escapes honoured) so
            # that "//" or "/*" inside it starts no comment
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(text[i:j])
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def includes(root):
    """(folder of the file, relative path, line, include text, included
    path below nmmSolid/) for every nmmSolid include below root"""
    for dirPath, dirNames, fileNames in os.walk(root):
        dirNames.sort()
        for fileName in sorted(fileNames):
            if not fileName.endswith(SOURCE_SUFFIXES):
                continue
            path = os.path.join(dirPath, fileName)
            rel = os.path.relpath(path, root)
            folder = rel.split(os.sep, 1)[0] if os.sep in rel else ""
            with open(path, encoding="utf-8", errors="replace") as f:
                text = withoutComments(f.read())
            for lineNo, line in enumerate(text.split("\n"), 1):
                m = INCLUDE.match(line)
                if m:
                    yield folder, rel, lineNo, line.strip(), m.group(1)


def findCycle(graph, members):
    """The shortest cycle through the first of members, as the folders it
    passes, starting and ending with that one"""
    start = members[0]
    previous = {start: None}
    queue = [start]
    while queue:
        node = queue.pop(0)
        for succ in sorted(graph.get(node, ())):
            if succ == start:
                path = [node]
                while previous[path[-1]] is not None:
                    path.append(previous[path[-1]])
                return path[::-1] + [start]
            if succ in members and succ not in previous:
                previous[succ] = node
                queue.append(succ)
    return [start]


def stronglyConnected(graph):
    """Tarjan's strongly connected components with more than one folder"""
    index = {}
    low = {}
    stack = []
    onStack = set()
    components = []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        onStack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in onStack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                onStack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                components.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return components


def check(root, layersFile):
    layers, errors = readLayers(layersFile)
    rank = {name: i for i, name in enumerate(layers)}
    # Paths as from the project: src/nmmSolid/solver/...
    base = os.path.dirname(os.path.dirname(root))
    layersName = os.path.relpath(layersFile, base)

    def place(rel):
        return os.path.relpath(os.path.join(root, rel), base)

    # (c) folders on disk that the order does not place
    for entry in sorted(os.listdir(root)):
        if os.path.isdir(os.path.join(root, entry)) and entry not in rank:
            errors.append(
                f"{place(entry)}: folder '{entry}' is not in {layersName}: "
                "list it where it belongs in the order")

    edges = {}          # (from, to) -> first (file, line, include)
    count = 0
    for folder, rel, lineNo, text, target in includes(root):
        count += 1
        where = f"{place(rel)}:{lineNo}: {text}"
        if "/" not in target:
            errors.append(f"{where}: a library header is in a folder of "
                          f"a layer, not directly in nmmSolid/")
            continue
        to = target.split("/", 1)[0]
        if not folder:
            errors.append(f"{where}: {rel} is not in a folder of a layer")
            continue
        if to == folder:
            continue
        edges.setdefault((folder, to), where)
        if to not in rank:
            errors.append(f"{where}: folder '{to}' is not in {layersName}")
        elif folder in rank and rank[to] > rank[folder]:
            # (a)
            errors.append(f"{where}: {folder} includes {to}, which comes "
                          f"after it in {layersName}")

    # (b) cycles, over every folder (listed or not)
    graph = {}
    for a, b in edges:
        graph.setdefault(a, set()).add(b)
    for component in stronglyConnected(graph):
        cycle = findCycle(graph, component)
        lines = [f"cycle between folders {', '.join(component)}: "
                 + " -> ".join(cycle)]
        for a, b in zip(cycle, cycle[1:]):
            lines.append(f"    {a} -> {b} at {edges[(a, b)]}")
        errors.append("\n".join(lines))

    return errors, count, layers


def main(argv):
    if len(argv) not in (2, 3):
        sys.stderr.write(__doc__)
        return 2
    root = os.path.abspath(argv[1])
    layersFile = os.path.abspath(argv[2]) if len(argv) == 3 \
        else os.path.join(root, "layers")
    errors, count, layers = check(root, layersFile)
    for e in errors:
        print(e)
    if errors:
        print(f"\n{len(errors)} layering error(s) in {root}")
        return 1
    print(f"{count} includes in {root} keep the layers "
          f"{' < '.join(layers)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
