#!/usr/bin/python3
"""Reads a DXF file with ezdxf (an independent reader) and compares it with the expected
cutting pattern. Usage: check_dxf.py FILE.dxf EXPECTED.json

EXPECTED.json: {"tolerance": mm, "paths": [{"layer": "CUT", "closed": true,
"points": [[x, y], ...]}, ...]}. Prints one JSON object: the audit's error and fix counts,
$INSUNITS, the DXF version, every layer (colour, linetype, on/off), the entity types, the largest
distance of an expected point from the curve read back on its layer, and the closed paths that
did not read back closed."""

import json
import math
import sys

import ezdxf


def curves_of(doc, tolerance):
    """Every curve in model space as (layer, points, closed)."""
    curves = []
    for e in doc.modelspace():
        kind = e.dxftype()
        if kind == "LWPOLYLINE":
            pts = [(p[0], p[1]) for p in e.get_points("xy")]
            curves.append((e.dxf.layer, pts, bool(e.closed), kind))
        elif kind == "POLYLINE":
            pts = [(v.dxf.location.x, v.dxf.location.y) for v in e.vertices]
            curves.append((e.dxf.layer, pts, bool(e.is_closed), kind))
        elif kind == "LINE":
            curves.append((e.dxf.layer, [(e.dxf.start.x, e.dxf.start.y),
                                         (e.dxf.end.x, e.dxf.end.y)], False, kind))
        elif kind == "SPLINE":
            tool = e.construction_tool()
            pts = [(p.x, p.y) for p in tool.flattening(tolerance / 20.0, segments=8)]
            ctrl = e.control_points
            closed = len(ctrl) > 1 and math.dist(ctrl[0][:2], ctrl[-1][:2]) < 1e-9
            curves.append((e.dxf.layer, pts, closed or bool(e.closed), kind))
    return curves


def segment_distance(p, a, b):
    abx, aby = b[0] - a[0], b[1] - a[1]
    length2 = abx * abx + aby * aby
    t = 0.0
    if length2 > 0.0:
        t = max(0.0, min(1.0, ((p[0] - a[0]) * abx + (p[1] - a[1]) * aby) / length2))
    return math.hypot(p[0] - a[0] - t * abx, p[1] - a[1] - t * aby)


class SegmentGrid:
    """Segments of one curve bucketed by cell, for nearest-segment queries."""

    def __init__(self, points, closed, cell):
        self.cell = cell
        self.buckets = {}
        pts = list(points) + ([points[0]] if closed and points else [])
        self.segments = list(zip(pts, pts[1:])) or [(pts[0], pts[0])]
        for i, (a, b) in enumerate(self.segments):
            for cx in range(int(math.floor(min(a[0], b[0]) / cell)),
                            int(math.floor(max(a[0], b[0]) / cell)) + 1):
                for cy in range(int(math.floor(min(a[1], b[1]) / cell)),
                                int(math.floor(max(a[1], b[1]) / cell)) + 1):
                    self.buckets.setdefault((cx, cy), []).append(i)

    def distance(self, p):
        cx, cy = int(math.floor(p[0] / self.cell)), int(math.floor(p[1] / self.cell))
        best = math.inf
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for i in self.buckets.get((cx + dx, cy + dy), ()):
                    best = min(best, segment_distance(p, *self.segments[i]))
        return best


def main():
    path, expected_path = sys.argv[1], sys.argv[2]
    with open(expected_path, encoding="utf-8") as f:
        expected = json.load(f)
    tolerance = expected["tolerance"]
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    layers = {}
    for layer in doc.layers:
        layers[layer.dxf.name] = {"color": layer.color, "linetype": layer.dxf.linetype,
                                  "on": layer.is_on()}
    curves = curves_of(doc, tolerance)
    cell = 5.0
    grids = [(layer, SegmentGrid(pts, closed, cell), closed) for layer, pts, closed, _ in curves
             if pts]
    # Which curves pass near a point: only those are compared with an expected path.
    near = {}
    for index, (layer, grid, _) in enumerate(grids):
        for key in grid.buckets:
            near.setdefault((layer,) + key, set()).add(index)
    max_error = 0.0
    not_closed = 0
    missing = 0
    for want in expected["paths"]:
        best = math.inf
        best_closed = False
        first = want["points"][0]
        cx, cy = int(math.floor(first[0] / cell)), int(math.floor(first[1] / cell))
        candidates = set()
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                candidates |= near.get((want["layer"], cx + dx, cy + dy), set())
        for index in sorted(candidates):
            layer, grid, closed = grids[index]
            error = 0.0
            for p in want["points"]:
                error = max(error, grid.distance(p))
                if error >= best:
                    break
            if error < best:
                best, best_closed = error, closed
        if math.isinf(best):
            missing += 1
            continue
        max_error = max(max_error, best)
        if want["closed"] and not best_closed:
            not_closed += 1
    print(json.dumps({
        "audit_errors": len(auditor.errors),
        "audit_fixes": len(auditor.fixes),
        "audit_messages": [str(e.message) for e in auditor.errors][:5],
        "dxfversion": doc.dxfversion,
        "insunits": doc.header.get("$INSUNITS", None),
        "layers": layers,
        "entity_types": sorted({kind for _, _, _, kind in curves} |
                               {e.dxftype() for e in doc.modelspace()}),
        "texts": sorted(e.dxf.text for e in doc.modelspace() if e.dxftype() == "TEXT"),
        "text_rotations": sorted(round(e.dxf.rotation, 6) for e in doc.modelspace()
                                 if e.dxftype() == "TEXT"),
        "max_error": max_error,
        "not_closed": not_closed,
        "missing": missing,
    }))


if __name__ == "__main__":
    main()
