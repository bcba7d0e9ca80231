#!/usr/bin/python3
"""Test nmmPlot's block outlines and force chains on a synthetic frame.

Usage:
    checkNmmPlotContacts.py --plot <nmmPlot> --work <dir>

Writes, with VTK, a frame of four square blocks whose geometry is known
(block 0: four triangles around its centre; block 1: 2 x 2 quads; block
2: two triangles; block 3: one quad) and its contacts file, whose pairs
are known: 0-1 bonded (two closed points, and an open one whose force
must not count), 1-2 sliding (one of its two closed points slides), 1-3
bonded with its bond intact and in tension, 0-2 open, and a contact of
block 1 with itself (a joint) that joins no two bodies. Then:

  - loads nmmPlot as a module and checks its functions: the outlines are
    exactly each block's outer edges (not the edges its cells share), the
    centroids are the squares' centres, the pairs, their summed forces
    and categories are the ones above, the pairs' contact points are where
    their forces act, the segments join the right centroids (or end at the
    contact point for a wall; a big block and a U-shaped box are walls,
    unit squares are not), the widths are proportional to |force| with the largest
    at -chainScale, and each category is drawn in its own colour;
  - runs nmmPlot with -outlines -contacts on the frame and on a .series
    with -time: exit 0, the frame's own contacts file is used, the PNG
    has the outline and chain colours;
  - errors exit 1 naming the file: a missing .vtp, a .vtp without
    blockA/blockB, a series frame without its contacts file; no PNG.

Exit code 0 when every check passes, 1 otherwise.

SPDX-License-Identifier: GPL-3.0-or-later
"""

import argparse
import importlib.machinery
import importlib.util
import json
import shutil
import subprocess
import sys
from pathlib import Path

failures = []


def check(cond, what):
    print("%s: %s" % ("ok  " if cond else "FAIL", what))
    if not cond:
        failures.append(what)


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def load_nmmPlot(path):
    """nmmPlot as a module (it has no .py suffix, so name its loader)."""
    loader = importlib.machinery.SourceFileLoader("nmmPlot", str(path))
    spec = importlib.util.spec_from_loader("nmmPlot", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


# --------------------------------------------------------------------------
# The synthetic frame
# --------------------------------------------------------------------------
def square_blocks():
    """points (n, 2), cells (point lists), blockIds, and per block the set
    of its outer edges as point pairs and its centroid."""
    pts, cells, blocks, outer, centre = [], [], [], {}, {}

    def add(xy):
        pts.append(xy)
        return len(pts) - 1

    # Block 0: [0,1]^2, four triangles around the centre
    c = [add(p) for p in [(0, 0), (1, 0), (1, 1), (0, 1), (0.5, 0.5)]]
    for k in range(4):
        cells.append([c[k], c[(k + 1) % 4], c[4]])
        blocks.append(0)
    outer[0] = {frozenset((c[k], c[(k + 1) % 4])) for k in range(4)}
    centre[0] = (0.5, 0.5)

    # Block 1: [1,2]x[0,1], 2 x 2 quads (its own points: the solver
    # duplicates them across blocks)
    g = {(i, j): add((1 + 0.5*i, 0.5*j)) for j in range(3) for i in range(3)}
    for j in range(2):
        for i in range(2):
            cells.append([g[(i, j)], g[(i + 1, j)], g[(i + 1, j + 1)],
                          g[(i, j + 1)]])
            blocks.append(1)
    ring = [(0, 0), (1, 0), (2, 0), (2, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
    outer[1] = {frozenset((g[ring[k]], g[ring[(k + 1) % 8]]))
                for k in range(8)}
    centre[1] = (1.5, 0.5)

    # Block 2: [0.5,1.5]x[1,2], two triangles along a diagonal
    d = [add(p) for p in [(0.5, 1), (1.5, 1), (1.5, 2), (0.5, 2)]]
    cells += [[d[0], d[1], d[2]], [d[0], d[2], d[3]]]
    blocks += [2, 2]
    outer[2] = {frozenset((d[k], d[(k + 1) % 4])) for k in range(4)}
    centre[2] = (1.0, 1.5)

    # Block 3: [2,3]x[0,1], one quad
    e = [add(p) for p in [(2, 0), (3, 0), (3, 1), (2, 1)]]
    cells.append(e)
    blocks.append(3)
    outer[3] = {frozenset((e[k], e[(k + 1) % 4])) for k in range(4)}
    centre[3] = (2.5, 0.5)
    return pts, cells, blocks, outer, centre


# x, y, contactState, bondIntact, normalForce, blockA, blockB
CONTACTS = [
    (1.0, 0.25, 1, 0, 2.0, 0, 1),
    (1.0, 0.75, 1, 0, 3.0, 1, 0),
    (1.0, 0.5, 0, 0, 100.0, 0, 1),    # open: its force does not count
    (1.0, 1.0, 2, 0, 10.0, 2, 1),
    (1.5, 1.0, 1, 0, 2.0, 1, 2),
    (2.0, 0.5, 1, 1, -4.0, 1, 3),     # an intact bond in tension
    (0.5, 1.0, 0, 0, 0.0, 0, 2),
    (1.5, 0.5, 1, 0, 7.0, 1, 1),      # across a joint of block 1
]
# (pair, summed normal force of its closed points, category)
EXPECTED = [((0, 1), 5.0, "bonded"), ((0, 2), 0.0, "open"),
            ((1, 2), 12.0, "sliding"), ((1, 3), -4.0, "cemented")]


def write_frame(path, pts, cells, blocks, time):
    from vtkmodules.vtkCommonCore import vtkPoints, vtkIntArray, vtkDoubleArray
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid, VTK_POLYGON
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    grid = vtkUnstructuredGrid()
    p = vtkPoints()
    for x, y in pts:
        p.InsertNextPoint(x, y, 0.0)
    grid.SetPoints(p)
    for c in cells:
        grid.InsertNextCell(VTK_POLYGON, len(c), c)
    ids = vtkIntArray()
    ids.SetName("blockId")
    for b in blocks:
        ids.InsertNextValue(b)
    grid.GetCellData().AddArray(ids)
    tv = vtkDoubleArray()
    tv.SetName("TimeValue")
    tv.InsertNextValue(time)
    grid.GetFieldData().AddArray(tv)
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(str(path))
    w.SetInputData(grid)
    w.Write()


def write_contacts(path, rows, without=()):
    from vtkmodules.vtkCommonCore import vtkPoints, vtkIntArray, vtkDoubleArray
    from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    poly = vtkPolyData()
    p = vtkPoints()
    verts = vtkCellArray()
    for r in rows:
        verts.InsertNextCell(1)
        verts.InsertCellPoint(p.InsertNextPoint(r[0], r[1], 0.0))
    poly.SetPoints(p)
    poly.SetVerts(verts)
    for col, name, kind in [(2, "contactState", vtkIntArray),
                            (3, "bondIntact", vtkIntArray),
                            (4, "normalForce", vtkDoubleArray),
                            (5, "blockA", vtkIntArray),
                            (6, "blockB", vtkIntArray)]:
        if name in without:
            continue
        a = kind()
        a.SetName(name)
        for r in rows:
            a.InsertNextValue(r[col])
        poly.GetPointData().AddArray(a)
    w = vtkXMLPolyDataWriter()
    w.SetFileName(str(path))
    w.SetInputData(poly)
    w.Write()


# --------------------------------------------------------------------------
# Checks
# --------------------------------------------------------------------------
def check_functions(np, plot, pts, cells, blocks, outer, centre):
    x = np.array(pts, dtype=float)
    outlines = plot.block_outlines(cells, blocks)
    check(sorted(outlines) == [0, 1, 2, 3], "outlines: one entry per block")
    for b in sorted(outer):
        got = [frozenset(e) for e in outlines.get(b, [])]
        check(len(got) == len(set(got)) and set(got) == outer[b],
              "outlines: block %d has exactly its %d outer edges (got %d)"
              % (b, len(outer[b]), len(got)))
    # The 2 x 2 block's sides are two cells long: a wrong key (the block's
    # four corners, say) would give four edges, not eight
    check(len(outlines[1]) == 8, "outlines: block 1 has 8 outer segments")

    centroids = plot.block_centroids(x, cells, blocks)
    check(all(np.allclose(centroids[b], centre[b]) for b in centre),
          "centroids: the squares' centres %s" % centroids)
    # A shifted frame: the centroids follow (no digits lost far away)
    far = plot.block_centroids(x + 1e6, cells, blocks)
    check(all(np.allclose(far[b], np.array(centre[b]) + 1e6, atol=1e-6)
              for b in centre), "centroids: exact 1e6 m from the origin")

    check(plot.wall_blocks(x, cells, blocks) == set(),
          "walls: none among four unit squares")
    check_walls(np, plot)
    check_broken(np, plot)

    cols = list(zip(*CONTACTS))
    pairs, forces, categories, points = plot.contact_pairs(
        cols[2], cols[4], cols[5], cols[6], cols[3],
        np.array(cols[:2]).T)
    check([tuple(p) for p in pairs] == [e[0] for e in EXPECTED],
          "pairs: %s (the joint contact of block 1 left out)"
          % [tuple(p) for p in pairs])
    check(np.allclose(forces, [e[1] for e in EXPECTED]),
          "pairs: summed normal forces of the closed points %s" % forces)
    check(categories == [e[2] for e in EXPECTED],
          "pairs: categories %s" % categories)

    # Where the closed points' forces act: 2 N at y 0.25 and 3 N at 0.75;
    # the open pair's only point; 10 N at x 1 and 2 N at 1.5
    check(np.allclose(points, [(1, 0.55), (0.5, 1), (13/12, 1), (2, 0.5)]),
          "pairs: contact points weighted by |force| %s" % points.tolist())

    segments = plot.chain_segments(pairs, centroids, points)
    want = np.array([[centre[p], centre[q]] for (p, q), _, _ in EXPECTED])
    check(segments.shape == (4, 2, 2) and np.allclose(segments, want),
          "segments join the pairs' centroids")
    walled = plot.chain_segments(pairs, centroids, points, walls={0, 2})
    check(np.allclose(walled[0], [(1, 0.55), centre[1]])
          and np.isnan(walled[1]).all()
          and np.allclose(walled[2], [centre[1], (13/12, 1)])
          and np.allclose(walled[3], want[3]),
          "segments: a wall's end at the contact point, wall-wall not drawn")

    widths = plot.chain_widths(forces, 6.0)
    check(np.allclose(widths, [2.5, 0.0, 6.0, 2.0]),
          "widths: 6 pt for |12 N|, in proportion to |force| %s" % widths)

    colours = {k: plot.chain_style(k)[1] for k in plot.CHAIN_STYLES}
    check(len(set(colours.values())) == len(colours),
          "styles: one colour per category %s" % colours)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import to_rgba
    for showOpen in (False, True):
        fig, ax = plt.subplots()
        drawn = plot.draw_chains(ax, segments, widths, categories, showOpen)
        want = ["bonded", "cemented", "sliding"] + (["open"] if showOpen
                                                    else [])
        check(sorted(drawn) == sorted(want),
              "draw_chains (open %s): %s drawn" % (showOpen, sorted(drawn)))
        for k, (pair, force, category) in enumerate(EXPECTED):
            if category not in drawn:
                continue
            coll = drawn[category]
            segs = coll.get_segments()
            lw = coll.get_linewidths()
            rgba = coll.get_colors()
            w = plot.OPEN_WIDTH if category == "open" else widths[k]
            check(len(segs) == 1 and np.allclose(segs[0], want_seg(
                  centre, pair)) and np.allclose(lw, [w])
                  and np.allclose(rgba[0], to_rgba(colours[category])),
                  "draw_chains: %s pair %s from centroid to centroid, "
                  "width %g, colour %s" % (category, pair, w,
                                           colours[category]))
        plt.close(fig)
    fig, ax = plt.subplots()
    tiny = plot.draw_chains(ax, segments[:1], np.array([1e-3]), ["bonded"],
                            False)
    check(np.allclose(tiny["bonded"].get_linewidths(), [plot.MIN_WIDTH]),
          "draw_chains: a weak closed pair at the minimum width")
    plt.close(fig)


def check_broken(np, plot):
    """Pairs with a broken bond: an open one (a crack) is drawn without
    -openPairs, a closed stuck one is told from a stuck one that never had
    a bond, and sliding and an intact bond still come first."""
    # contactState, bondIntact, bondBroken, normalForce, blockA, blockB
    rows = [
        (0, 0, 1, 0.0, 0, 1),     # (0, 1): open, its bond broke: a crack
        (0, 0, 0, 0.0, 0, 1),
        (1, 0, 1, 3.0, 1, 2),     # (1, 2): stuck after its bond broke
        (1, 0, 0, 2.0, 2, 3),     # (2, 3): stuck, never bonded
        (2, 0, 1, 5.0, 3, 4),     # (3, 4): sliding after its bond broke
        (1, 1, 0, 1.0, 4, 5),     # (4, 5): one point still cemented,
        (0, 0, 1, 0.0, 5, 4),     #         another's bond broke
        (0, 0, 0, 0.0, 5, 6),     # (5, 6): open, never bonded
    ]
    c = list(zip(*rows))
    _, forces, categories, _ = plot.contact_pairs(
        c[0], c[3], c[4], c[5], bondIntact=c[1], bondBroken=c[2])
    want = ["broken", "broken", "bonded", "sliding", "cemented", "open"]
    check(categories == want, "broken bonds: categories %s, want %s"
          % (categories, want))
    check(np.allclose(forces, [0, 3, 2, 5, 1, 0]),
          "broken bonds: forces of the closed points %s" % forces)
    _, _, without, _ = plot.contact_pairs(c[0], c[3], c[4], c[5],
                                          bondIntact=c[1])
    check(without == ["open", "bonded", "bonded", "sliding", "cemented",
                      "open"],
          "broken bonds: files without bondBroken as before %s" % without)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    segments = np.array([[[k, 0.0], [k, 1.0]] for k in range(len(want))])
    widths = plot.chain_widths(forces, 5.0)
    fig, ax = plt.subplots()
    drawn = plot.draw_chains(ax, segments, widths, categories, False)
    check("broken" in drawn and len(drawn["broken"].get_segments()) == 2
          and "open" not in drawn,
          "broken bonds: both broken pairs drawn without -openPairs, the "
          "open pair not")
    check(np.allclose(sorted(drawn["broken"].get_linewidths()),
                      [plot.MIN_WIDTH, 3.0]),
          "broken bonds: the open crack at the minimum width, the loaded "
          "pair by its force")
    plt.close(fig)


def check_walls(np, plot):
    """A 3 x 3 block among unit squares, and a U-shaped box whose centroid
    is in its hollow, are walls; the squares are not."""
    pts, cells, blocks = [], [], []

    def rect(x0, y0, x1, y1, block):
        n = len(pts)
        pts.extend([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
        cells.append([n, n + 1, n + 2, n + 3])
        blocks.append(block)

    for b in range(4):
        rect(2*b, 5, 2*b + 1, 6, b)
    rect(0, 10, 3, 13, 4)
    for x0, y0, x1, y1 in [(0, 0, 0.2, 1), (0.2, 0, 0.8, 0.2),
                           (0.8, 0, 1, 1)]:
        rect(x0 + 10, y0, x1 + 10, y1, 5)
    walls = plot.wall_blocks(np.array(pts, dtype=float), cells, blocks)
    check(walls == {4, 5}, "walls: the big block and the U-shaped box %s"
          % sorted(walls))


def want_seg(centre, pair):
    return [centre[pair[0]], centre[pair[1]]]


def colour_pixels(np, img, colour):
    from matplotlib.colors import to_rgb
    rgb = (np.array(to_rgb(colour))*255).round()
    px = (img[..., :3]*255).round().reshape(-1, 3)
    return int((np.abs(px - rgb).max(axis=1) <= 2).sum())


def dark_pixels(np, img):
    return int((img[..., :3].max(axis=-1) < 0.25).sum())


def check_runs(np, plot, a, work, frame, series, vtp):
    import matplotlib.image as mpimg
    cmd = [sys.executable, a.plot]
    dpi = 60
    plain = work/"plain.png"
    rc, out, err = run(cmd + [str(frame), "-field", "blockId", "-dpi",
                              str(dpi), "-o", str(plain)])
    check(rc == 0, "plain frame: exit 0 (%s)" % err.strip())

    png = work/"chains.png"
    rc, out, err = run(cmd + [str(frame), "-field", "blockId", "-outlines",
                              "-contacts", "-chainScale", "6", "-dpi",
                              str(dpi), "-o", str(png)])
    check(rc == 0, "-outlines -contacts: exit 0 (%s)" % err.strip())
    check(vtp.name in out and "4 pairs" in out
          and "bonded 1, broken 0, cemented 1, sliding 1" in out,
          "-contacts reads the frame's %s: %s" % (vtp.name, out.strip()))
    if png.is_file() and plain.is_file():
        img, ref = mpimg.imread(str(png)), mpimg.imread(str(plain))
        check(img.shape[:2] == (6*dpi, 8*dpi), "PNG size 6*dpi x 8*dpi")
        # Anti-aliased lines a pixel wide rarely hit their exact colour:
        # count the near-black pixels, which the plain frame has only in
        # its text and axes
        dark, before = dark_pixels(np, img), dark_pixels(np, ref)
        check(dark > before + 300,
              "outlines drawn: %d near-black pixels, %d without -outlines"
              % (dark, before))
        for k in ("bonded", "cemented", "sliding"):
            n = colour_pixels(np, img, plot.chain_style(k)[1])
            check(n > 20, "%s chain colour drawn (%d pixels)" % (k, n))

    rc, out, err = run(cmd + [str(frame), "-field", "blockId", "-contacts",
                              str(vtp), "-openPairs", "-o",
                              str(work/"open.png")])
    check(rc == 0 and (work/"open.png").is_file(),
          "-contacts FILE.vtp -openPairs: exit 0 (%s)" % err.strip())

    rc, out, err = run(cmd + [str(series), "-time", "latest", "-field",
                              "blockId", "-contacts", "-outlines", "-o",
                              str(work/"series.png")])
    check(rc == 0 and vtp.name in out,
          "series -time latest: the latest frame's %s (%s)"
          % (vtp.name, (out + err).strip()))

    rc, out, err = run(cmd + [str(frame), "-field", "blockId", "-contacts",
                              "-walls", "3", "-o", str(work/"walls.png")])
    check(rc == 0 and "walls: 3" in out, "-walls 3: exit 0 (%s)"
          % (out + err).strip())
    rc, out, err = run(cmd + [str(frame), "-field", "blockId", "-contacts",
                              "-walls", "9", "-o", str(work/"bad.png")])
    check(rc == 1 and "no block 9" in err, "-walls 9: exit 1 (%s)"
          % err.strip())

    empty = work/"empty.vtp"
    write_contacts(empty, [])
    rc, out, err = run(cmd + [str(frame), "-field", "blockId", "-contacts",
                              str(empty), "-o", str(work/"empty.png")])
    check(rc == 0 and "0 pairs" in out,
          "a contacts file without contacts: exit 0, no chains")

    # Errors: exit 1 naming the file, no PNG
    bad = work/"bad.png"
    missing = work/"VTK"/"nowhere.vtp"
    rc, out, err = run(cmd + [str(frame), "-field", "blockId", "-contacts",
                              str(missing), "-o", str(bad)])
    check(rc == 1 and str(missing) in err,
          "missing .vtp: exit 1 naming it (%s)" % err.strip())
    old = work/"old.vtp"
    write_contacts(old, CONTACTS, without=("blockA", "blockB"))
    rc, out, err = run(cmd + [str(frame), "-field", "blockId", "-contacts",
                              str(old), "-o", str(bad)])
    check(rc == 1 and str(old) in err and "'blockA'" in err
          and "'blockB'" in err,
          "a .vtp without blockA/blockB: exit 1 naming the file and arrays "
          "(%s)" % err.strip().splitlines()[:1])
    rc, out, err = run(cmd + [str(series), "-time", "0", "-field", "blockId",
                              "-contacts", "-o", str(bad)])
    check(rc == 1 and "contacts_0.vtp" in err,
          "series -time 0 without contacts_0.vtp: exit 1 naming it (%s)"
          % err.strip())
    check(not bad.exists(), "no PNG written on errors")

    rc, out, err = run(cmd + ["-help"])
    check(rc == 0 and all(o in out for o in ("-outlines", "-contacts",
                                             "-chainScale", "-openPairs")),
          "-help documents -outlines -contacts -chainScale -openPairs")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--plot", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    try:
        import numpy as np
        import matplotlib
        matplotlib.use("Agg")
        import vtkmodules.vtkIOXML  # noqa: F401
    except ImportError as e:
        sys.exit("checkNmmPlotContacts: %s cannot import %s: install the "
                 "Debian packages python3-numpy python3-matplotlib "
                 "python3-vtk9" % (sys.executable, e))

    work = Path(a.work)
    shutil.rmtree(work, ignore_errors=True)
    vtkDir = work/"VTK"
    vtkDir.mkdir(parents=True)
    pts, cells, blocks, outer, centre = square_blocks()
    write_frame(vtkDir/"squares_0.vtu", pts, cells, blocks, 0.0)
    frame = vtkDir/"squares_10.vtu"
    write_frame(frame, pts, cells, blocks, 1.0)
    vtp = vtkDir/"contacts_10.vtp"
    write_contacts(vtp, CONTACTS)
    series = vtkDir/"squares.vtu.series"
    series.write_text(json.dumps({"file-series-version": "1.0", "files": [
        {"name": "squares_0.vtu", "time": 0.0},
        {"name": "squares_10.vtu", "time": 1.0}]}))

    plot = load_nmmPlot(a.plot)
    check_functions(np, plot, pts, cells, blocks, outer, centre)
    check_runs(np, plot, a, work, frame, series, vtp)

    if failures:
        print("%d check(s) failed" % len(failures))
        return 1
    print("All nmmPlot contact checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
