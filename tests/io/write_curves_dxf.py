#!/usr/bin/python3
"""Writes the DXF files the curve import is tested on with ezdxf (a writer DevSurf did not
write). Usage: write_curves_dxf.py DIR. Writes DIR/curves.dxf (mm: every entity kind the import
reads, with known geometry, plus a text, a block insert and a mesh that are not curves) and
DIR/cm.dxf (centimetres: one LINE)."""

import math
import sys

import ezdxf

out = sys.argv[1]

doc = ezdxf.new("R2010")
doc.header["$INSUNITS"] = 4
msp = doc.modelspace()
msp.add_line((0, 0, 0), (100, 50, 25), dxfattribs={"layer": "LINES"})
# Open, elevation 5: (0,0) bulge 1 to (20,0) is a half circle about (10,0) below the x axis.
msp.add_lwpolyline([(0, 0, 0, 0, 1), (20, 0), (20, 10)], format="xyseb",
                   dxfattribs={"layer": "LW", "elevation": 5})
msp.add_polyline3d([(0, 0, 0), (10, 20, 30), (40, 50, 60)], dxfattribs={"layer": "POLY3D"})
# C(t) = (30t, 30t², 30t³) as a cubic Bezier.
msp.add_open_spline([(0, 0, 0), (10, 0, 0), (20, 10, 0), (30, 30, 30)], degree=3,
                    dxfattribs={"layer": "SPLINES"})
# A quarter of the circle of radius 20 about the origin, exactly (rational quadratic).
msp.add_rational_spline([(20, 0, 0), (20, 20, 0), (0, 20, 0)], [1, math.sqrt(0.5), 1],
                        degree=2, dxfattribs={"layer": "SPLINES"})
msp.add_circle((100, 100, 0), 25, dxfattribs={"layer": "CIRCLES"})
msp.add_arc((0, 0, 0), 10, 0, 90, dxfattribs={"layer": "CIRCLES"})
# Seen from below (extrusion -z): the OCS centre (10, 0) is (-10, 0) in the world.
msp.add_arc((10, 0, 0), 5, 0, 180, dxfattribs={"layer": "FLIPPED", "extrusion": (0, 0, -1)})
# Half an ellipse about (50, -40): semi-axes 30 (along x) and 15, from (80, -40) over the top.
msp.add_ellipse((50, -40, 0), major_axis=(30, 0, 0), ratio=0.5, start_param=0,
                end_param=math.pi, dxfattribs={"layer": "ELLIPSES"})
msp.add_text("not a curve", dxfattribs={"layer": "TEXT"})
block = doc.blocks.new(name="MARK")
block.add_line((0, 0), (1, 1))
msp.add_blockref("MARK", (5, 5))
doc.saveas(out + "/curves.dxf")

cm = ezdxf.new("R2010")
cm.header["$INSUNITS"] = 5
cm.modelspace().add_line((0, 0, 0), (1, 2, 3))
cm.saveas(out + "/cm.dxf")
