#!/usr/bin/env python3
"""Generate (and check) the scenes shipped in walkrad's assets/ folder.

What it builds (all in the `walkrad-scene/1` format of spec/scene-format.md):

  office.json   units m.  A furnished office, 5 m (x) by 4 m (z) by 2.8 m high,
                seen from inside (one inward box).  Lights: a flush ceiling panel
                (a filled hole in the room's `top` face, material "light panel")
                and a window (a filled hole in the wall z = 0, material "sky").
                Furniture: desk, chair, cabinet, bookshelf, monitor and a
                24-sided round pillar from floor to ceiling.  A door (a filled
                hole, not emissive) in the wall z = 4.
  kitchen.json  units in.  A kitchen at the scale of the thesis' "Brooks'
                kitchen" (chapter 6: 933 polygons, 18,615 patches at a 12 in
                patch size): a 240 x 96 x 180 in room (x by y by z) with an L of
                base cabinets (doors, drawer fronts, handles), counter tops, a
                recessed sink with faucet, upper cabinets, refrigerator, range
                with burners, oven door and hood, dishwasher, microwave, a table
                with four chairs, a pendant lamp, three windows (filled with an
                emissive "sky"), a door, four flush ceiling light panels,
                under-cabinet lights and a hood light.  Every piece of
                furniture is its own object so it can be dragged.
  furnace.json  units m.  The furnace test: one closed inward 1 m cube whose six
                faces all use one material, reflectance 0.5 and emission 1, so
                the exact radiance everywhere is E / (1 - rho) = 2.

(assets/cornell.json is written by hand and is not touched by this script.)

Regenerate (from the repository root; the files are written next to this
script's parent folder, i.e. into assets/):

    python3 assets/tools/make_scenes.py            # write the three files, then check them
    python3 assets/tools/make_scenes.py --check    # only check the files on disk
    python3 assets/tools/make_scenes.py --check some/other/scene.json ...
    python3 assets/tools/make_scenes.py --describe # also list objects, lights and holes in world space

The output is deterministic (fixed key order, numbers rounded to 6 decimals).

The checker is independent of the builders: it reads the JSON back and
verifies what the loader will refuse plus a few modelling rules of our own:
  * only keys of the spec; format, units; materials defined, in range, and all
    of them used; unique object names; a `default` camera;
  * profiles with >= 3 points, strictly convex, nonzero area; from < to;
  * face names valid for the solid; holes convex (our rule), strictly inside
    their face with a margin (side faces: 0 < u < edge length, 0 < v < to -
    from; top/bottom: inside the profile polygon), not touching each other, no
    holes on tapered side faces or open faces; fill materials defined;
  * (geometry, our rules) no two solids overlap (touching is allowed), every
    solid lies inside an inward (room) solid, every camera is inside a room
    (unless the room has an open face) and not inside a solid.
It prints the number of surfaces per file (every face that is not open counts
one, each filled hole one more), an estimate of the surfaces left after
merging coplanar, touching faces of one material, and a rough patch count.
Exit status 1 when any file fails.
"""

import argparse
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ASSETS = os.path.dirname(HERE)
FORMAT = "walkrad-scene/1"

# ---------------------------------------------------------------------------
# Section: building helpers
# ---------------------------------------------------------------------------
#
# Boxes are prisms along y with the profile (x0,z0) (x1,z0) (x1,z1) (x0,z1),
# so their side faces are:
SIDE_ZMIN = "side 0"   # plane z = z0, u = x - x0
SIDE_XMAX = "side 1"   # plane x = x1, u = z - z0
SIDE_ZMAX = "side 2"   # plane z = z1, u = x1 - x
SIDE_XMIN = "side 3"   # plane x = x0, u = z1 - z
# and v = y - y0 on all of them; `top` is y = y1, `bottom` y = y0, both with
# hole coordinates (x, z).


def box(x0, x1, y0, y1, z0, z1, material, inward=False):
    """A box solid [x0,x1] x [y0,y1] x [z0,z1], swept along y."""
    assert x0 < x1 and y0 < y1 and z0 < z1, (x0, x1, y0, y1, z0, z1)
    solid = {
        "profile": [[x0, z0], [x1, z0], [x1, z1], [x0, z1]],
        "axis": "y",
        "from": y0,
        "to": y1,
    }
    if inward:
        solid["inward"] = True
    solid["material"] = material
    return solid


def ngon(cx, cz, r, n, phase_deg=0.0):
    """n points on a circle of radius r around (cx, cz), counter-clockwise."""
    pts = []
    for k in range(n):
        a = math.radians(phase_deg) + 2.0 * math.pi * k / n
        pts.append([cx + r * math.cos(a), cz + r * math.sin(a)])
    return pts


def cylinder(cx, cz, r, y0, y1, n, material, phase_deg=None):
    """A vertical n-sided prism approximating a cylinder."""
    if phase_deg is None:
        phase_deg = 180.0 / n  # flat faces towards +-x and +-z
    return {"profile": ngon(cx, cz, r, n, phase_deg), "axis": "y",
            "from": y0, "to": y1, "material": material}


def face(solid, name):
    return solid.setdefault("faces", {}).setdefault(name, {})


def _side_uv(solid, n, p3):
    """(u, v) of local point p3 = (x, y, z) on side n of a y-axis prism."""
    assert solid["axis"] == "y"
    prof = solid["profile"]
    a, b = prof[n], prof[(n + 1) % len(prof)]
    ex, ez = b[0] - a[0], b[1] - a[1]
    length = math.hypot(ex, ez)
    u = ((p3[0] - a[0]) * ex + (p3[2] - a[1]) * ez) / length
    v = p3[1] - solid["from"]
    return [u, v]


def add_hole(solid, face_name, r0, r1, fill=None):
    """Cut a rectangular hole into a face of a y-axis box solid.

    r0, r1 are the hole's ranges in the solid's own coordinates:
      top/bottom:        r0 = (x0, x1), r1 = (z0, z1)
      side 0 / side 2:   r0 = (x0, x1), r1 = (y0, y1)
      side 1 / side 3:   r0 = (z0, z1), r1 = (y0, y1)
    and are converted to the face coordinates of the spec.
    """
    (a0, a1), (b0, b1) = r0, r1
    corners = [(a0, b0), (a1, b0), (a1, b1), (a0, b1)]
    if face_name in ("top", "bottom"):
        poly = [[a, b] for a, b in corners]
    else:
        n = int(face_name.split()[1])
        if n in (0, 2):
            poly = [_side_uv(solid, n, (a, b, 0.0)) for a, b in corners]
        else:
            poly = [_side_uv(solid, n, (0.0, b, a)) for a, b in corners]
    hole = {"polygon": poly}
    if fill is not None:
        hole["fill"] = fill
    face(solid, face_name).setdefault("holes", []).append(hole)
    return hole


def obj(name, solids, position=(0, 0, 0), rotate_y=0, movable=True):
    o = {"name": name}
    o["movable"] = bool(movable)
    o["position"] = list(position)
    o["rotate_y"] = rotate_y
    o["solids"] = solids
    return o


def camera(position, look_at, fov_y=60, up=(0, 1, 0)):
    return {"position": list(position), "look_at": list(look_at),
            "up": list(up), "fov_y": fov_y}


def scene(units, patch_size, materials, objects, cameras):
    return {"format": FORMAT, "units": units,
            "settings": {"patch_size": patch_size},
            "materials": materials, "objects": objects, "cameras": cameras}


def mat(reflectance, emission=None):
    m = {"reflectance": list(reflectance)}
    if emission is not None:
        m["emission"] = list(emission)
    return m


# ---------------------------------------------------------------------------
# Section: JSON output (pretty, arrays of numbers on one line)
# ---------------------------------------------------------------------------

def _num(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    v = round(float(v), 6)
    if v == 0.0:
        v = 0.0  # no "-0"
    if v.is_integer():
        return str(int(v))
    return repr(v)


def _is_numeric_array(x):
    if not isinstance(x, list):
        return False
    for e in x:
        if isinstance(e, list):
            if not all(isinstance(f, (int, float)) and not isinstance(f, bool) for f in e):
                return False
        elif not (isinstance(e, (int, float)) and not isinstance(e, bool)):
            return False
    return True


def _dump(x, level, indent):
    pad = " " * (indent * level)
    pad1 = " " * (indent * (level + 1))
    if isinstance(x, dict):
        if not x:
            return "{}"
        items = [pad1 + json.dumps(k) + ": " + _dump(v, level + 1, indent) for k, v in x.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(x, list):
        if _is_numeric_array(x):
            return "[" + ", ".join(_dump(e, level, indent) for e in x) + "]"
        if not x:
            return "[]"
        items = [pad1 + _dump(e, level + 1, indent) for e in x]
        return "[\n" + ",\n".join(items) + "\n" + pad + "]"
    if isinstance(x, str):
        return json.dumps(x)
    if isinstance(x, (bool, int, float)):
        return _num(x)
    if x is None:
        return "null"
    raise TypeError(type(x))


def to_json(doc):
    return _dump(doc, 0, 1) + "\n"


# ---------------------------------------------------------------------------
# Section: office.json (metres)
# ---------------------------------------------------------------------------

def build_office():
    L, H, W = 5.0, 2.8, 4.0  # x, y, z
    materials = {
        "wall": mat([0.75, 0.75, 0.75]),
        "ceiling": mat([0.8, 0.8, 0.8]),
        "floor": mat([0.4, 0.35, 0.3]),
        "light panel": mat([0.8, 0.8, 0.8], [12, 12, 11]),
        "sky": mat([0, 0, 0], [2, 2.5, 3.2]),
        "door": mat([0.5, 0.34, 0.22]),
        "wood": mat([0.55, 0.35, 0.2]),
        "metal": mat([0.5, 0.5, 0.52]),
        "cabinet": mat([0.65, 0.65, 0.6]),
        "concrete": mat([0.6, 0.58, 0.55]),
        "fabric": mat([0.2, 0.25, 0.45]),
        "black": mat([0.05, 0.05, 0.05]),
        "screen": mat([0.02, 0.02, 0.03]),
        "book red": mat([0.6, 0.15, 0.12]),
        "book green": mat([0.15, 0.4, 0.2]),
        "book blue": mat([0.15, 0.2, 0.5]),
        "paper": mat([0.85, 0.83, 0.78]),
    }
    objects = []

    # Room: inward box.  side 0 is the wall z = 0 (u = x), side 2 the wall z = W
    # (u = L - x), top the ceiling.
    room = box(0, L, 0, H, 0, W, "wall", inward=True)
    face(room, "bottom")["material"] = "floor"
    face(room, "top")["material"] = "ceiling"
    add_hole(room, "top", (1.9, 3.1), (1.7, 2.3), fill="light panel")     # 1.2 x 0.6 m panel
    add_hole(room, SIDE_ZMIN, (1.7, 3.3), (0.9, 2.0), fill="sky")         # 1.6 x 1.1 m window
    add_hole(room, SIDE_ZMAX, (3.6, 4.5), (0.01, 2.05), fill="door")      # door, 1 cm sill strip
    objects.append(obj("room", [room], movable=False))

    # Desk under the window (local origin: centre of its footprint, front is +z).
    desk = [
        box(-0.8, 0.8, 0.72, 0.75, -0.4, 0.4, "wood"),          # top slab
        box(-0.78, -0.74, 0.0, 0.72, -0.38, 0.38, "wood"),      # left side panel
        box(0.74, 0.78, 0.0, 0.72, -0.38, 0.38, "wood"),        # right side panel
        box(-0.74, 0.74, 0.3, 0.72, -0.36, -0.34, "wood"),      # modesty panel
    ]
    objects.append(obj("desk", desk, position=(2.5, 0, 0.6)))

    # Monitor on the desk (desk top at y = 0.75).
    monitor = [
        box(-0.12, 0.12, 0.0, 0.015, -0.1, 0.08, "black"),      # foot
        box(-0.025, 0.025, 0.015, 0.12, -0.06, -0.03, "black"),  # neck
        box(-0.3, 0.3, 0.12, 0.48, -0.065, -0.03, "black"),     # housing
    ]
    hole_box = monitor[2]
    add_hole(hole_box, SIDE_ZMAX, (-0.28, 0.28), (0.14, 0.46), fill="screen")
    objects.append(obj("monitor", monitor, position=(2.5, 0.75, 0.45), rotate_y=-8))

    # Chair in front of the desk, facing -z, turned a little.
    chair = [
        box(-0.23, 0.23, 0.42, 0.47, -0.22, 0.22, "fabric"),    # seat
        box(-0.23, -0.2, 0.0, 0.42, -0.22, -0.19, "metal"),     # legs
        box(0.2, 0.23, 0.0, 0.42, -0.22, -0.19, "metal"),
        box(-0.23, -0.2, 0.0, 0.42, 0.19, 0.22, "metal"),
        box(0.2, 0.23, 0.0, 0.42, 0.19, 0.22, "metal"),
        box(-0.23, -0.2, 0.47, 0.92, 0.19, 0.22, "metal"),      # back posts
        box(0.2, 0.23, 0.47, 0.92, 0.19, 0.22, "metal"),
        box(-0.2, 0.2, 0.55, 0.9, 0.19, 0.22, "fabric"),        # backrest
    ]
    objects.append(obj("chair", chair, position=(2.45, 0, 1.38), rotate_y=15))

    # Cabinet against the wall x = 0; built with its front towards +z and
    # turned by 90 degrees (+z -> +x), its back (local z = -0.42) on the wall.
    cab = [
        box(-0.45, 0.45, 0.0, 1.9, -0.42, 0.0, "cabinet"),
        box(-0.44, -0.005, 0.05, 1.85, 0.003, 0.023, "cabinet"),   # doors
        box(0.005, 0.44, 0.05, 1.85, 0.003, 0.023, "cabinet"),
        box(-0.06, -0.04, 0.85, 1.05, 0.023, 0.043, "metal"),     # handles
        box(0.04, 0.06, 0.85, 1.05, 0.023, 0.043, "metal"),
    ]
    objects.append(obj("cabinet", cab, position=(0.42, 0, 3.0), rotate_y=90))

    # Bookshelf against the wall x = L, front towards -x (local +z turned by -90).
    shelf = [
        box(-0.45, -0.43, 0.0, 2.0, -0.3, 0.0, "wood"),         # sides
        box(0.43, 0.45, 0.0, 2.0, -0.3, 0.0, "wood"),
        box(-0.43, 0.43, 1.98, 2.0, -0.3, 0.0, "wood"),         # top
        box(-0.43, 0.43, 0.0, 0.08, -0.3, 0.0, "wood"),         # plinth / bottom
        box(-0.43, 0.43, 0.55, 0.57, -0.29, 0.0, "wood"),       # shelves
        box(-0.43, 0.43, 1.02, 1.04, -0.29, 0.0, "wood"),
        box(-0.43, 0.43, 1.49, 1.51, -0.29, 0.0, "wood"),
        box(-0.43, 0.43, 0.08, 1.98, -0.3, -0.29, "wood"),      # back panel
    ]
    books = [  # (x0, x1, height, depth, material) standing on a shelf
        (-0.4, -0.33, 0.3, 0.22, "book red"), (-0.33, -0.27, 0.28, 0.2, "book blue"),
        (-0.27, -0.2, 0.32, 0.23, "book green"), (-0.2, -0.15, 0.26, 0.2, "paper"),
        (0.05, 0.14, 0.3, 0.24, "book blue"), (0.14, 0.2, 0.29, 0.22, "book red"),
    ]
    for i, (x0, x1, h, d, m) in enumerate(books):
        y0 = 0.57 if i < 4 else 1.04
        shelf.append(box(x0, x1, y0, y0 + h, -0.28, -0.28 + d, m))
    objects.append(obj("bookshelf", shelf, position=(L - 0.3, 0, 1.45), rotate_y=-90))

    # Round pillar, 24 sides, floor to ceiling.
    pillar = cylinder(3.9, 2.9, 0.18, 0.0, H, 24, "concrete")
    objects.append(obj("pillar", [pillar], movable=False))

    cameras = {
        "default": camera((0.5, 1.6, 3.7), (3.6, 1.0, 0.8), 60),
        "window": camera((2.5, 1.6, 3.6), (2.5, 1.3, 0.0), 60),
        "overview": camera((4.6, 2.5, 0.3), (1.0, 0.5, 3.0), 70),
    }
    return scene("m", 0.25, materials, objects, cameras)


# ---------------------------------------------------------------------------
# Section: kitchen.json (inches)
# ---------------------------------------------------------------------------
#
# Plan (x along the back wall, z away from it, y up):
#   back wall z = 0:  refrigerator | base cabinets | sink (window above) |
#                     dishwasher | base cabinet | corner cabinet
#   east wall x = 240: corner | base | range (hood above) | drawers | base
#   west wall x = 0:  window by the table;  south wall z = 180: window, door
#   table with four chairs and a pendant lamp at (80, 120).

KW, KH, KD = 240.0, 96.0, 180.0     # room x, y, z
BASE_DEPTH = 23.0                   # carcass depth from the wall
TOE_DEPTH = 20.0                    # plinth depth (recessed toe kick)
TOE_H = 4.0
BASE_TOP = 34.5                     # carcass top = counter underside
COUNTER_TOP = 36.0
COUNTER_DEPTH = 25.0
UPPER_Y0, UPPER_Y1, UPPER_DEPTH = 54.0, 90.0, 12.0
DOOR_T = 0.75                       # door / drawer front thickness
GAP = 0.25                          # gap between fronts and from the carcass


def run_box(run, s0, s1, d0, d1, y0, y1, material):
    """A box in a run's frame: s along the wall, d out from the wall.

    run "back": the wall z = 0, s = x, d = z.
    run "east": the wall x = KW, s = z, d = KW - x.
    """
    if run == "back":
        return box(s0, s1, y0, y1, d0, d1, material)
    if run == "east":
        return box(KW - d1, KW - d0, y0, y1, s0, s1, material)
    raise ValueError(run)


def fronts_split(s0, s1, count):
    """Split [s0, s1] into count fronts separated by GAP, inset by GAP."""
    a, b = s0 + GAP, s1 - GAP
    w = (b - a - GAP * (count - 1)) / count
    return [(a + i * (w + GAP), a + i * (w + GAP) + w) for i in range(count)]


def base_cabinet(name, run, s0, s1, kind, front_span=None):
    """A base cabinet: plinth, carcass and fronts with handles.

    kind: "door" (drawer over one or two doors) or "drawers" (four drawers).
    front_span: the part of [s0, s1] that carries fronts (corner cabinets).
    """
    fs0, fs1 = front_span or (s0, s1)
    d_front = BASE_DEPTH + GAP
    d_face = d_front + DOOR_T
    solids = [
        run_box(run, s0, s1, 0.0, TOE_DEPTH, 0.0, TOE_H, "plinth"),
        run_box(run, s0, s1, 0.0, BASE_DEPTH, TOE_H, BASE_TOP, "cabinet"),
    ]
    y_lo, y_hi = TOE_H + 0.5, BASE_TOP - 0.25
    if kind == "drawers":
        n = 4
        h = (y_hi - y_lo - GAP * (n - 1)) / n
        for i in range(n):
            y0 = y_lo + i * (h + GAP)
            solids.append(run_box(run, fs0 + GAP, fs1 - GAP, d_front, d_face, y0, y0 + h, "cabinet door"))
            mid = 0.5 * (fs0 + fs1)
            solids.append(run_box(run, mid - 3, mid + 3, d_face, d_face + 0.75,
                                  y0 + h - 2.5, y0 + h - 1.75, "steel"))
    else:
        drawer_y0 = y_hi - 6.0
        solids.append(run_box(run, fs0 + GAP, fs1 - GAP, d_front, d_face, drawer_y0, y_hi, "cabinet door"))
        mid = 0.5 * (fs0 + fs1)
        solids.append(run_box(run, mid - 3, mid + 3, d_face, d_face + 0.75,
                              drawer_y0 + 2.75, drawer_y0 + 3.5, "steel"))
        count = 2 if fs1 - fs0 > 24 else 1
        doors = fronts_split(fs0, fs1, count)
        for i, (a, b) in enumerate(doors):
            solids.append(run_box(run, a, b, d_front, d_face, y_lo, drawer_y0 - GAP, "cabinet door"))
            # knob near the top, on the opening edge
            k = (b - 2.5, b - 1.5) if (count == 1 or i == 0) else (a + 1.5, a + 2.5)
            solids.append(run_box(run, k[0], k[1], d_face, d_face + 1.0,
                                  drawer_y0 - 3.5, drawer_y0 - 2.5, "steel"))
    return obj(name, solids, movable=False)


def upper_cabinet(name, run, s0, s1, y0=UPPER_Y0, y1=UPPER_Y1, depth=UPPER_DEPTH,
                  front_span=None, light=None):
    """A wall cabinet: carcass, one or two doors with knobs at the bottom.

    light: optional (s0, s1, d0, d1) strip cut into the carcass bottom and
    filled with the under-cabinet light material.
    """
    fs0, fs1 = front_span or (s0, s1)
    carcass = run_box(run, s0, s1, 0.0, depth, y0, y1, "cabinet")
    solids = [carcass]
    if light is not None:
        ls0, ls1, ld0, ld1 = light
        if run == "back":
            add_hole(carcass, "bottom", (ls0, ls1), (ld0, ld1), fill="under-cabinet light")
        else:
            add_hole(carcass, "bottom", (KW - ld1, KW - ld0), (ls0, ls1), fill="under-cabinet light")
    count = 2 if fs1 - fs0 > 24 else 1
    for i, (a, b) in enumerate(fronts_split(fs0, fs1, count)):
        solids.append(run_box(run, a, b, depth, depth + DOOR_T, y0 + GAP, y1 - GAP, "cabinet door"))
        k = (b - 2.5, b - 1.5) if (count == 1 or i == 0) else (a + 1.5, a + 2.5)
        solids.append(run_box(run, k[0], k[1], depth + DOOR_T, depth + DOOR_T + 1.0,
                              y0 + 2.0, y0 + 3.0, "steel"))
    return obj(name, solids, movable=False)


def window_trim(wall, a0, a1, y0, y1):
    """Trim, sill and a mullion around a window hole (a0..a1 along the wall).

    wall: "back" (z = 0, a = x), "west" (x = 0, a = z), "south" (z = KD, a = x).
    Returns the solids (in world coordinates).
    """
    t, w, sill_d = 0.75, 1.5, 2.5

    def wb(s0, s1, d0, d1, yy0, yy1, m):
        if wall == "back":
            return box(s0, s1, yy0, yy1, d0, d1, m)
        if wall == "west":
            return box(d0, d1, yy0, yy1, s0, s1, m)
        if wall == "south":
            return box(s0, s1, yy0, yy1, KD - d1, KD - d0, m)
        raise ValueError(wall)

    mid = 0.5 * (a0 + a1)
    return [
        wb(a0 - w, a0, 0, t, y0, y1 + w, "trim"),                       # left jamb
        wb(a1, a1 + w, 0, t, y0, y1 + w, "trim"),                       # right jamb
        wb(a0, a1, 0, t, y1, y1 + w, "trim"),                           # head
        wb(a0 - w - 0.5, a1 + w + 0.5, 0, sill_d, y0 - w, y0, "trim"),  # sill
        wb(mid - 0.5, mid + 0.5, 0, t, y0, y1, "trim"),                 # mullion
    ]


def build_kitchen():
    materials = {
        "wall": mat([0.78, 0.76, 0.7]),
        "ceiling": mat([0.85, 0.85, 0.85]),
        "floor": mat([0.5, 0.44, 0.36]),
        "trim": mat([0.88, 0.88, 0.85]),
        "cabinet": mat([0.55, 0.38, 0.22]),
        "cabinet door": mat([0.6, 0.42, 0.25]),
        "plinth": mat([0.15, 0.12, 0.1]),
        "counter": mat([0.3, 0.3, 0.32]),
        "backsplash": mat([0.8, 0.78, 0.72]),
        "steel": mat([0.6, 0.6, 0.62]),
        "appliance": mat([0.85, 0.85, 0.83]),
        "black glass": mat([0.04, 0.04, 0.05]),
        "burner": mat([0.08, 0.08, 0.08]),
        "table wood": mat([0.5, 0.32, 0.18]),
        "chair wood": mat([0.42, 0.26, 0.14]),
        "lampshade": mat([0.8, 0.75, 0.6]),
        "door": mat([0.45, 0.3, 0.2]),
        "sky": mat([0, 0, 0], [2, 2.5, 3.2]),
        "ceiling light": mat([0.8, 0.8, 0.8], [10, 10, 9]),
        "pendant light": mat([0.8, 0.8, 0.8], [10, 9, 7]),
        "under-cabinet light": mat([0.8, 0.8, 0.8], [4, 4, 3.6]),
        "hood light": mat([0.8, 0.8, 0.8], [5, 4.8, 4.2]),
    }
    objects = []

    # --- room -------------------------------------------------------------
    room = box(0, KW, 0, KH, 0, KD, "wall", inward=True)
    face(room, "bottom")["material"] = "floor"
    face(room, "top")["material"] = "ceiling"
    for cx, cz in ((60, 50), (170, 50), (60, 145), (170, 140)):      # 2 ft x 2 ft panels
        add_hole(room, "top", (cx - 12, cx + 12), (cz - 12, cz + 12), fill="ceiling light")
    win_back = (94.0, 134.0, 46.0, 80.0)        # x0 x1 y0 y1, over the sink
    win_west = (96.0, 144.0, 30.0, 84.0)        # z0 z1 y0 y1, by the table
    win_south = (40.0, 88.0, 36.0, 84.0)        # x0 x1 y0 y1
    door = (150.0, 186.0, 0.75, 81.0)           # x0 x1 y0 y1 (0.75 in threshold)
    add_hole(room, SIDE_ZMIN, win_back[:2], win_back[2:], fill="sky")
    add_hole(room, SIDE_XMIN, win_west[:2], win_west[2:], fill="sky")
    add_hole(room, SIDE_ZMAX, win_south[:2], win_south[2:], fill="sky")
    add_hole(room, SIDE_ZMAX, door[:2], door[2:], fill="door")
    objects.append(obj("room", [room], movable=False))

    # --- windows and door trim --------------------------------------------
    objects.append(obj("sink window trim", window_trim("back", *win_back), movable=False))
    objects.append(obj("west window trim", window_trim("west", *win_west), movable=False))
    objects.append(obj("south window trim", window_trim("south", *win_south), movable=False))
    x0, x1, _, y1 = door
    door_trim = [
        box(x0 - 2.5, x0, 0, y1, KD - 0.75, KD, "trim"),
        box(x1, x1 + 2.5, 0, y1, KD - 0.75, KD, "trim"),
        box(x0 - 2.5, x1 + 2.5, y1, y1 + 2.5, KD - 0.75, KD, "trim"),
        box(x0, x1, 0, 0.75, KD - 1.0, KD, "trim"),                  # threshold
        box(x1 - 4, x1 - 2, 35, 37, KD - 2.5, KD, "steel"),           # door knob
    ]
    objects.append(obj("door trim", door_trim, movable=False))

    # --- refrigerator and the cabinet above it ---------------------------
    fr_body = box(0.5, 35.5, 0, 69, 0, 28, "appliance")
    freezer = box(0.75, 14.25, 1, 68.5, 28, 29.5, "appliance")
    fridge_door = box(14.75, 35.25, 1, 68.5, 28, 29.5, "appliance")
    add_hole(freezer, SIDE_ZMAX, (3.5, 11.5), (38, 50), fill="black glass")   # dispenser
    fridge = [fr_body, freezer, fridge_door,
              box(12.0, 13.0, 30, 56, 29.5, 31.0, "steel"),
              box(16.0, 17.0, 30, 56, 29.5, 31.0, "steel")]
    objects.append(obj("refrigerator", fridge, movable=False))
    objects.append(upper_cabinet("cabinet over refrigerator", "back", 0, 36, y0=72, y1=90, depth=24))

    # --- base cabinets, back run (fronts face +z) ------------------------
    objects.append(base_cabinet("base cabinet 1", "back", 36, 66, "door"))
    objects.append(base_cabinet("drawer cabinet 1", "back", 66, 96, "drawers"))

    # Sink base: low carcass, apron front, two doors; an inward basin set
    # into an opening of the counter top.
    sink_base = [
        box(96, 132, 0, TOE_H, 0, TOE_DEPTH, "plinth"),
        box(96, 132, TOE_H, 25, 0, BASE_DEPTH, "cabinet"),
        box(96, 132, 25, BASE_TOP, BASE_DEPTH - 2, BASE_DEPTH, "cabinet"),     # apron behind the false front
        box(96 + GAP, 132 - GAP, 28.25, BASE_TOP - 0.25, BASE_DEPTH + GAP, BASE_DEPTH + GAP + DOOR_T, "cabinet door"),
    ]
    d_face = BASE_DEPTH + GAP + DOOR_T
    for i, (a, b) in enumerate(fronts_split(96, 132, 2)):
        sink_base.append(box(a, b, TOE_H + 0.5, 28.0, BASE_DEPTH + GAP, d_face, "cabinet door"))
        k = (b - 2.5, b - 1.5) if i == 0 else (a + 1.5, a + 2.5)
        sink_base.append(box(k[0], k[1], 24.5, 25.5, d_face, d_face + 1.0, "steel"))
    objects.append(obj("sink cabinet", sink_base, movable=False))
    basin = box(99, 129, 26, BASE_TOP, 3, 20, "steel", inward=True)
    face(basin, "top")["open"] = True
    faucet = [
        basin,
        cylinder(114, 2.0, 0.9, COUNTER_TOP, 42, 12, "steel"),
        box(113.25, 114.75, 42, 43.5, 1.5, 9, "steel"),           # spout
        box(108, 110, COUNTER_TOP, 38, 1, 3, "steel"),           # taps
        box(118, 120, COUNTER_TOP, 38, 1, 3, "steel"),
    ]
    objects.append(obj("sink", faucet, movable=False))

    # Dishwasher.
    dw = [
        box(132, 156, 0, BASE_TOP, 0, BASE_DEPTH, "appliance"),
        box(132 + GAP, 156 - GAP, TOE_H + 0.5, BASE_TOP - 0.5, BASE_DEPTH + GAP, d_face, "appliance"),
        box(136, 152, 30.5, 31.25, d_face, d_face + 0.75, "steel"),
    ]
    add_hole(dw[1], SIDE_ZMAX, (137, 151), (BASE_TOP - 3.0, BASE_TOP - 1.5), fill="black glass")  # control strip
    objects.append(obj("dishwasher", dw, movable=False))

    objects.append(base_cabinet("base cabinet 2", "back", 156, 186, "door"))
    # Corner: carcass to the east wall, fronts only where the east run does not cover it.
    objects.append(base_cabinet("corner cabinet", "back", 186, 240, "door",
                                front_span=(186, KW - COUNTER_DEPTH - 1.0)))

    # --- base cabinets, east run (fronts face -x) -------------------------
    objects.append(base_cabinet("base cabinet 3", "east", BASE_DEPTH, 54, "door",
                                front_span=(BASE_DEPTH + 1.0, 54)))

    # Range between z = 54 and 84: body, cooktop, burners, oven door, knobs.
    r0, r1 = 54.0, 84.0
    range_body = box(KW - 24, KW, 0, 35, r0, r1, "steel")
    cooktop = box(KW - COUNTER_DEPTH, KW, 35, COUNTER_TOP, r0, r1, "black glass")
    oven = box(KW - 24 - DOOR_T, KW - 24, 8, 30, r0 + 1, r1 - 1, "steel")
    add_hole(oven, SIDE_XMIN, (r0 + 5, r1 - 5), (14, 25), fill="black glass")       # oven window
    rng = [range_body, cooktop, oven,
           box(KW - 26.25, KW - 24 - DOOR_T, 26.5, 27.5, r0 + 4, r1 - 4, "steel"),  # oven handle
           box(KW - 24 - DOOR_T, KW - 24, 1, 7, r0 + 1, r1 - 1, "steel"),         # drawer
           box(KW - 3, KW, COUNTER_TOP, 42, r0, r1, "steel")]                     # backguard
    for bx, bz in ((KW - 17.5, r0 + 7.5), (KW - 17.5, r1 - 7.5), (KW - 8.5, r0 + 7.5), (KW - 8.5, r1 - 7.5)):
        rng.append(cylinder(bx, bz, 3.5, COUNTER_TOP, COUNTER_TOP + 0.6, 16, "burner"))
    for kz in (r0 + 3, r0 + 8, r1 - 8, r1 - 3):
        rng.append(box(KW - 25, KW - 24, 31.5, 33.5, kz - 1, kz + 1, "burner"))
    objects.append(obj("range", rng, movable=False))

    objects.append(base_cabinet("drawer cabinet 2", "east", 84, 114, "drawers"))
    objects.append(base_cabinet("base cabinet 4", "east", 114, 138, "door"))

    # --- counter tops and backsplash -------------------------------------
    y0, y1 = BASE_TOP, COUNTER_TOP
    counters = [
        box(36, 99, y0, y1, 0, COUNTER_DEPTH, "counter"),           # left of the sink
        box(99, 129, y0, y1, 0, 3, "counter"),                      # behind the basin
        box(99, 129, y0, y1, 20, COUNTER_DEPTH, "counter"),         # in front of the basin
        box(129, KW, y0, y1, 0, COUNTER_DEPTH, "counter"),          # right of the sink to the corner
        box(KW - COUNTER_DEPTH, KW, y0, y1, COUNTER_DEPTH, r0, "counter"),
        box(KW - COUNTER_DEPTH, KW, y0, y1, r1, 138, "counter"),
    ]
    objects.append(obj("counter top", counters, movable=False))
    splash = [
        box(36, KW - 0.75, COUNTER_TOP, 40, 0, 0.75, "backsplash"),
        box(KW - 0.75, KW, COUNTER_TOP, 40, 0, r0, "backsplash"),
        box(KW - 0.75, KW, COUNTER_TOP, 40, r1, 138, "backsplash"),
    ]
    objects.append(obj("backsplash", splash, movable=False))

    # --- upper cabinets -------------------------------------------------------
    objects.append(upper_cabinet("wall cabinet 1", "back", 36, 64))
    objects.append(upper_cabinet("wall cabinet 2", "back", 64, 92, light=(68, 88, 8, 10)))
    objects.append(upper_cabinet("wall cabinet 3", "back", 136, 166, light=(140, 162, 8, 10)))
    objects.append(upper_cabinet("wall cabinet 4", "back", 166, 196))
    # Corner: runs to the east wall, doors only up to the east run.
    objects.append(upper_cabinet("wall cabinet 5", "back", 196, KW,
                                 front_span=(196, KW - UPPER_DEPTH - DOOR_T - 0.5)))
    objects.append(upper_cabinet("wall cabinet 6", "east", UPPER_DEPTH, r0,
                                 front_span=(UPPER_DEPTH + 1.0, r0)))
    objects.append(upper_cabinet("wall cabinet 7", "east", r1, 114))
    objects.append(upper_cabinet("wall cabinet 8", "east", 114, 138))

    # Range hood with a light, and its chimney up to the ceiling.
    hood = box(KW - 20, KW, 66, 72, r0, r1, "steel")
    add_hole(hood, "bottom", (KW - 16, KW - 4), (r0 + 8, r1 - 8), fill="hood light")
    objects.append(obj("range hood", [hood, box(KW - 10, KW, 72, KH, r0 + 8, r1 - 8, "steel")],
                       movable=False))

    # Microwave on the counter.
    mw_body = box(158, 180, COUNTER_TOP, 49, 1.5, 17.5, "appliance")
    mw_door = box(158.5, 174, 36.5, 48.5, 17.5, 18.25, "appliance")
    add_hole(mw_door, SIDE_ZMAX, (160.5, 171.5), (39, 46), fill="black glass")
    mw = [mw_body, mw_door, box(174.5, 179.5, 37, 48.5, 17.5, 18.0, "black glass")]
    objects.append(obj("microwave", mw, movable=False))

    # --- table, chairs, pendant lamp -------------------------------------
    table = [box(-30, 30, 28.5, 30, -18, 18, "table wood")]
    for sx in (-1, 1):
        for sz in (-1, 1):
            xa, xb = sorted((sx * 25.5, sx * 28))
            za, zb = sorted((sz * 13.5, sz * 16))
            table.append(box(xa, xb, 0, 28.5, za, zb, "table wood"))
    for sz in (-1, 1):
        za, zb = sorted((sz * 14.25, sz * 15.25))
        table.append(box(-25.5, 25.5, 24.5, 28.5, za, zb, "table wood"))
    for sx in (-1, 1):
        xa, xb = sorted((sx * 26.25, sx * 27.25))
        table.append(box(xa, xb, 24.5, 28.5, -13.5, 13.5, "table wood"))
    tx, tz = 80.0, 120.0
    objects.append(obj("table", table, position=(tx, 0, tz)))

    def chair_solids():
        s = [box(-8, 8, 17, 18.5, -8, 8, "chair wood")]                       # seat
        for xa, xb in ((-8, -6.75), (6.75, 8)):
            for za, zb in ((-8, -6.75), (6.75, 8)):
                s.append(box(xa, xb, 0, 17, za, zb, "chair wood"))            # legs
            s.append(box(xa, xb, 18.5, 36, 6.75, 8, "chair wood"))           # back posts
        s.append(box(-6.75, 6.75, 30, 35, 7, 7.75, "chair wood"))             # back rails
        s.append(box(-6.75, 6.75, 22, 24, 7, 7.75, "chair wood"))
        return s

    # Built facing -z (back at +z); rotate_y turns them to face the table.
    chairs = [
        ("chair 1", (tx, 0, tz + 18 + 4 + 8), 3),       # south side, facing -z
        ("chair 2", (tx, 0, tz - 18 - 4 - 8), 180),     # north side, facing +z
        ("chair 3", (tx + 30 + 4 + 8, 0, tz), 90),      # east end, facing -x
        ("chair 4", (tx - 30 - 4 - 8, 0, tz), -95),     # west end, facing +x
    ]
    for name, pos, rot in chairs:
        objects.append(obj(name, chair_solids(), position=pos, rotate_y=rot))

    shade = {"profile": ngon(0, 0, 8, 12, 15), "axis": "y", "from": 66, "to": 74,
             "taper": {"kind": "linear", "scale": 0.3}, "material": "lampshade",
             "faces": {"bottom": {"material": "pendant light"}}}
    pendant = [shade,
               box(-0.25, 0.25, 74, 95, -0.25, 0.25, "steel"),            # cord
               cylinder(0, 0, 2.5, 95, KH, 8, "steel")]                   # canopy
    objects.append(obj("pendant lamp", pendant, position=(tx, 0, tz)))

    cameras = {
        "default": camera((18, 64, 168), (200, 36, 20), 60),
        "sink": camera((114, 64, 100), (114, 40, 0), 60),
        "table": camera((205, 60, 165), (80, 28, 110), 60),
        "high corner": camera((230, 88, 172), (60, 20, 30), 70),
    }
    return scene("in", 12, materials, objects, cameras)


# ---------------------------------------------------------------------------
# Section: furnace.json
# ---------------------------------------------------------------------------

def build_furnace():
    materials = {"furnace": mat([0.5, 0.5, 0.5], [1, 1, 1])}
    room = box(0, 1, 0, 1, 0, 1, "furnace", inward=True)
    objects = [obj("furnace", [room], movable=False)]
    cameras = {"default": camera((0.5, 0.5, 0.5), (0.5, 0.5, 0.0), 90)}
    return scene("m", 0.25, materials, objects, cameras)


SCENES = [("office.json", build_office), ("kitchen.json", build_kitchen),
          ("furnace.json", build_furnace)]
MIN_SURFACES = {"kitchen.json": 900}


# ---------------------------------------------------------------------------
# Section: checker (independent of the builders: works on the JSON only)
# ---------------------------------------------------------------------------

TOP_KEYS = {"format", "units", "settings", "materials", "objects", "cameras"}
SETTINGS_KEYS = {"patch_size"}
MATERIAL_KEYS = {"reflectance", "emission"}
OBJECT_KEYS = {"name", "movable", "position", "rotate_y", "solids", "patch_size"}
SOLID_KEYS = {"profile", "axis", "from", "to", "taper", "inward", "material", "faces", "patch_size"}
FACE_KEYS = {"material", "open", "patch_size", "holes"}
HOLE_KEYS = {"polygon", "fill"}
CAMERA_KEYS = {"position", "look_at", "up", "fov_y"}
UNITS = {"m", "cm", "mm", "in", "ft"}
UNIT_IN_M = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254, "ft": 0.3048}


class Report:
    def __init__(self, fname):
        self.fname = fname
        self.errors = []
        self.notes = []

    def err(self, path, msg):
        self.errors.append("%s: %s: %s" % (self.fname, path, msg))

    def note(self, path, msg):
        self.notes.append("%s: %s: %s" % (self.fname, path, msg))


def _isnum(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def _vec(x, n):
    return isinstance(x, list) and len(x) == n and all(_isnum(e) for e in x)


def _sub(a, b):
    return [a[i] - b[i] for i in range(len(a))]


def _dot(a, b):
    return sum(a[i] * b[i] for i in range(len(a)))


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _norm(a):
    return math.sqrt(_dot(a, a))


def _unit(a):
    n = _norm(a)
    return [e / n for e in a] if n > 0 else None


def poly_area2(pts):
    """Twice the signed area of a 2-D polygon."""
    s = 0.0
    for i in range(len(pts)):
        x0, y0 = pts[i]
        x1, y1 = pts[(i + 1) % len(pts)]
        s += x0 * y1 - x1 * y0
    return s


def poly_centroid(pts):
    a2 = poly_area2(pts)
    cx = cy = 0.0
    for i in range(len(pts)):
        x0, y0 = pts[i]
        x1, y1 = pts[(i + 1) % len(pts)]
        c = x0 * y1 - x1 * y0
        cx += (x0 + x1) * c
        cy += (y0 + y1) * c
    return [cx / (3 * a2), cy / (3 * a2)]


def convexity_problem(pts, scale):
    """None if pts is a strictly convex simple polygon, else a message."""
    n = len(pts)
    if n < 3:
        return "fewer than 3 points"
    eps = 1e-12 * scale * scale
    a2 = poly_area2(pts)
    if abs(a2) <= eps:
        return "zero area"
    sign = 1 if a2 > 0 else -1
    turn = 0.0
    for i in range(n):
        p0, p1, p2 = pts[i - 1], pts[i], pts[(i + 1) % n]
        e0, e1 = _sub(p1, p0), _sub(p2, p1)
        if math.hypot(*e1) <= 1e-9 * scale:
            return "repeated point %d" % ((i + 1) % n)
        c = e0[0] * e1[1] - e0[1] * e1[0]
        if c * sign <= eps:
            return "not strictly convex at point %d" % i
        turn += math.atan2(c, _dot(e0, e1))
    if abs(abs(turn) - 2 * math.pi) > 1e-6:
        return "self-intersecting (winds %.2f turns)" % (turn / (2 * math.pi))
    return None


def point_in_convex(q, pts, margin):
    """q strictly inside convex pts, at least `margin` from every edge."""
    sign = 1 if poly_area2(pts) > 0 else -1
    for i in range(len(pts)):
        a, b = pts[i], pts[(i + 1) % len(pts)]
        e = _sub(b, a)
        c = (e[0] * (q[1] - a[1]) - e[1] * (q[0] - a[0])) * sign / math.hypot(*e)
        if c <= margin:
            return False
    return True


def separation_2d(p, q):
    """Largest gap between two convex 2-D polygons along an edge normal
    (> 0: apart, <= 0: touching or overlapping)."""
    best = -math.inf
    for poly in (p, q):
        for i in range(len(poly)):
            a, b = poly[i], poly[(i + 1) % len(poly)]
            nrm = _unit([-(b[1] - a[1]), b[0] - a[0]])
            pa = [_dot(nrm, v) for v in p]
            pb = [_dot(nrm, v) for v in q]
            gap = max(min(pb) - max(pa), min(pa) - max(pb))
            best = max(best, gap)
    return best


def rot_y(p, deg):
    t = math.radians(deg)
    c, s = math.cos(t), math.sin(t)
    # positive angle turns +x toward -z
    return [p[0] * c + p[2] * s, p[1], -p[0] * s + p[2] * c]


def lift(axis, a, b, s):
    """Profile coordinates (a, b) and sweep coordinate s to local 3-D."""
    if axis == "x":
        return [s, a, b]
    if axis == "y":
        return [a, s, b]
    return [a, b, s]


class Solid:
    """A checked solid in world space (prism or linear taper only)."""

    def __init__(self, oi, si, oname, s, pos, rot):
        self.oi, self.si, self.oname, self.raw = oi, si, oname, s
        self.path = "objects[%d].solids[%d]" % (oi, si)
        self.inward = bool(s.get("inward", False))
        taper = s.get("taper", {"kind": "none"})
        self.kind = taper.get("kind", "none")
        self.pos, self.rot = pos, rot
        prof, ax, f, t = s["profile"], s["axis"], s["from"], s["to"]
        self.prof, self.axis, self.frm, self.to = prof, ax, f, t
        top = prof
        if self.kind == "linear":
            sc = taper.get("scale", 1.0)
            c = poly_centroid(prof)
            top = [[c[0] + sc * (p[0] - c[0]), c[1] + sc * (p[1] - c[1])] for p in prof]
        self.top_prof = top
        self.geometric = self.kind in ("none", "linear")
        if not self.geometric:
            return
        self.bot = [self.world(lift(ax, p[0], p[1], f)) for p in prof]
        self.topv = [self.world(lift(ax, p[0], p[1], t)) for p in top]
        self.verts = self.bot + self.topv
        n = len(prof)
        self.centroid = [sum(v[i] for v in self.verts) / len(self.verts) for i in range(3)]
        # faces as world polygons with outward (or inward) normals
        self.faces = {}
        self.faces["bottom"] = list(self.bot)
        self.faces["top"] = list(self.topv)
        for i in range(n):
            j = (i + 1) % n
            self.faces["side %d" % i] = [self.bot[i], self.bot[j], self.topv[j], self.topv[i]]
        self.normals = {}
        for k, poly in self.faces.items():
            nrm = _unit(newell(poly))
            if nrm is None:
                continue
            c = [sum(v[i] for v in poly) / len(poly) for i in range(3)]
            if _dot(nrm, _sub(c, self.centroid)) < 0:
                nrm = [-e for e in nrm]
            self.normals[k] = nrm          # outward of the solid
        dirs = []
        for i in range(n):
            j = (i + 1) % n
            dirs += [_sub(self.bot[j], self.bot[i]), _sub(self.topv[j], self.topv[i]),
                     _sub(self.topv[i], self.bot[i])]
        self.edges = unique_dirs(dirs)
        self.lo = [min(v[i] for v in self.verts) for i in range(3)]
        self.hi = [max(v[i] for v in self.verts) for i in range(3)]

    def world(self, p):
        q = rot_y(p, self.rot)
        return [q[i] + self.pos[i] for i in range(3)]

    def contains(self, q, margin):
        """q inside by at least margin (negative margin: allows q outside)."""
        for k, nrm in self.normals.items():
            p0 = self.faces[k][0]
            if _dot(nrm, _sub(q, p0)) > -margin:
                return False
        return True

    def face_frame(self, name):
        """Map face coordinates (u, v) of a prism face to world space."""
        ax, prof = self.axis, self.prof
        if name in ("top", "bottom"):
            s = self.to if name == "top" else self.frm
            return lambda uv: self.world(lift(ax, uv[0], uv[1], s))
        n = int(name.split()[1])
        a, b = prof[n], prof[(n + 1) % len(prof)]
        e = _unit(_sub(b, a))

        def m(uv):
            pa = a[0] + e[0] * uv[0]
            pb = a[1] + e[1] * uv[0]
            return self.world(lift(ax, pa, pb, self.frm + uv[1]))
        return m


def newell(poly):
    nrm = [0.0, 0.0, 0.0]
    for i in range(len(poly)):
        a, b = poly[i], poly[(i + 1) % len(poly)]
        nrm[0] += (a[1] - b[1]) * (a[2] + b[2])
        nrm[1] += (a[2] - b[2]) * (a[0] + b[0])
        nrm[2] += (a[0] - b[0]) * (a[1] + b[1])
    return nrm


def unique_dirs(dirs):
    out, seen = [], set()
    for d in dirs:
        u = _unit(d)
        if u is None:
            continue
        if u[0] < -1e-12 or (abs(u[0]) <= 1e-12 and (u[1] < -1e-12 or (abs(u[1]) <= 1e-12 and u[2] < 0))):
            u = [-e for e in u]
        key = tuple(round(e, 9) for e in u)
        if key not in seen:
            seen.add(key)
            out.append(u)
    return out


def penetration(va, na, ea, vb, nb, eb):
    """SAT for two convex point sets: the smallest overlap over all axes
    (<= 0: separated or touching)."""
    axes = list(na) + list(nb)
    for x in ea:
        for y in eb:
            c = _unit(_cross(x, y))
            if c is not None:
                axes.append(c)
    best = math.inf
    for ax in axes:
        pa = [_dot(ax, v) for v in va]
        pb = [_dot(ax, v) for v in vb]
        ov = min(max(pa), max(pb)) - max(min(pa), min(pb))
        if ov < best:
            best = ov
            if best <= 0:
                return best
    return best


def face_names(s):
    n = len(s["profile"])
    taper = s.get("taper", {"kind": "none"})
    if taper.get("kind") == "radial":
        k = int(taper.get("slices", 1))
        sides = ["side %d.%d" % (i, j) for i in range(n) for j in range(k)]
    else:
        sides = ["side %d" % i for i in range(n)]
    ends = []
    kind = taper.get("kind", "none")
    if kind == "radial":
        if not taper.get("both_ends", False):
            ends = ["bottom"]
    elif kind == "linear" and taper.get("scale", 1.0) == 0:
        ends = ["bottom"]
    else:
        ends = ["bottom", "top"]
    return ends, sides


def check_scene(path, describe=False):
    fname = os.path.basename(path)
    rep = Report(fname)

    def bad_const(c):
        raise ValueError("non-finite number %s" % c)
    try:
        with open(path) as fh:
            doc = json.load(fh, parse_constant=bad_const)
    except (OSError, ValueError) as e:
        rep.err("$", "cannot read: %s" % e)
        return rep, 0
    if not isinstance(doc, dict):
        rep.err("$", "not an object")
        return rep, 0
    for k in doc:
        if k not in TOP_KEYS:
            rep.err(k, "unknown key")
    if doc.get("format") != FORMAT:
        rep.err("format", "must be %r" % FORMAT)
    units = doc.get("units", "m")
    if units not in UNITS:
        rep.err("units", "unknown unit %r" % units)
        units = "m"
    scale = 1.0 / UNIT_IN_M[units]        # one metre in file units
    tol = 1e-6 * scale                    # geometric tolerance: a micrometre
    margin = 1e-4 * scale                 # holes keep 0.1 mm from edges and each other
    settings = doc.get("settings", {})
    for k in settings:
        if k not in SETTINGS_KEYS:
            rep.err("settings." + k, "unknown key")
    ps_default = settings.get("patch_size", 0.25 * scale)
    if not (_isnum(ps_default) and ps_default > 0):
        rep.err("settings.patch_size", "must be a positive number")
        ps_default = 0.25 * scale

    mats = doc.get("materials", {})
    used = set()
    if not isinstance(mats, dict):
        rep.err("materials", "not an object")
        mats = {}
    for name, m in mats.items():
        p = "materials.%s" % name
        if not isinstance(m, dict):
            rep.err(p, "not an object")
            continue
        for k in m:
            if k not in MATERIAL_KEYS:
                rep.err(p + "." + k, "unknown key")
        r = m.get("reflectance")
        if not _vec(r, 3) or not all(0 <= e <= 1 for e in r):
            rep.err(p + ".reflectance", "needs 3 numbers in 0..1")
        e = m.get("emission", [0, 0, 0])
        if not _vec(e, 3) or not all(x >= 0 for x in e):
            rep.err(p + ".emission", "needs 3 numbers >= 0")

    def use(mname, p):
        if not isinstance(mname, str) or mname not in mats:
            rep.err(p, "unknown material %r" % (mname,))
        else:
            used.add(mname)

    surfaces = 0
    patches = 0
    solids = []
    fills = []              # (world polygon, solid index, path)
    merge_faces = []        # (material, world polygon, solid, face name) of every surface
    names = set()
    objects = doc.get("objects", [])
    if not isinstance(objects, list) or not objects:
        rep.err("objects", "needs a non-empty list")
        objects = []
    for oi, o in enumerate(objects):
        op = "objects[%d]" % oi
        if not isinstance(o, dict):
            rep.err(op, "not an object")
            continue
        for k in o:
            if k not in OBJECT_KEYS:
                rep.err(op + "." + k, "unknown key")
        name = o.get("name")
        if not isinstance(name, str) or not name:
            rep.err(op + ".name", "missing")
        elif name in names:
            rep.err(op + ".name", "duplicate name %r" % name)
        names.add(name)
        if "movable" in o and not isinstance(o["movable"], bool):
            rep.err(op + ".movable", "not a boolean")
        pos = o.get("position", [0, 0, 0])
        if not _vec(pos, 3):
            rep.err(op + ".position", "needs 3 numbers")
            pos = [0, 0, 0]
        rot = o.get("rotate_y", 0)
        if not _isnum(rot):
            rep.err(op + ".rotate_y", "not a number")
            rot = 0
        ops = o.get("patch_size", ps_default)
        sl = o.get("solids")
        if not isinstance(sl, list) or not sl:
            rep.err(op + ".solids", "needs a non-empty list")
            continue
        for si, s in enumerate(sl):
            sp = "%s.solids[%d]" % (op, si)
            if not isinstance(s, dict):
                rep.err(sp, "not an object")
                continue
            nerr = len(rep.errors)
            for k in s:
                if k not in SOLID_KEYS:
                    rep.err(sp + "." + k, "unknown key")
            prof = s.get("profile")
            if not (isinstance(prof, list) and all(_vec(p, 2) for p in prof)):
                rep.err(sp + ".profile", "needs a list of [a, b] points")
                continue
            prob = convexity_problem(prof, scale)
            if prob:
                rep.err(sp + ".profile", prob)
                continue
            if s.get("axis") not in ("x", "y", "z"):
                rep.err(sp + ".axis", "must be x, y or z")
            f, t = s.get("from"), s.get("to")
            if not (_isnum(f) and _isnum(t) and f < t):
                rep.err(sp + ".from", "needs numbers from < to")
            if "inward" in s and not isinstance(s["inward"], bool):
                rep.err(sp + ".inward", "not a boolean")
            taper = s.get("taper", {"kind": "none"})
            kind = taper.get("kind") if isinstance(taper, dict) else None
            if kind == "none":
                extra = set(taper) - {"kind"}
            elif kind == "linear":
                extra = set(taper) - {"kind", "scale"}
                if not (_isnum(taper.get("scale")) and taper["scale"] >= 0):
                    rep.err(sp + ".taper.scale", "needs a number >= 0")
            elif kind == "radial":
                extra = set(taper) - {"kind", "slices", "both_ends"}
                sl_n = taper.get("slices")
                if not (isinstance(sl_n, int) and not isinstance(sl_n, bool) and sl_n >= 1):
                    rep.err(sp + ".taper.slices", "needs an integer >= 1")
            else:
                extra = set()
                rep.err(sp + ".taper", "unknown kind %r" % (kind,))
            for k in extra:
                rep.err(sp + ".taper." + k, "unknown key")
            if "material" not in s:
                rep.err(sp + ".material", "missing (our rule: every solid names one)")
            else:
                use(s["material"], sp + ".material")
            if len(rep.errors) > nerr:
                continue
            sps = s.get("patch_size", ops)
            ends, sides = face_names(s)
            valid = set(ends) | set(sides) | {"top", "bottom"}
            faces = s.get("faces", {})
            if not isinstance(faces, dict):
                rep.err(sp + ".faces", "not an object")
                faces = {}
            for fn in faces:
                if fn not in valid:
                    rep.err(sp + ".faces." + fn, "no such face")
            solid = Solid(oi, si, name, s, pos, rot)
            solid.sindex = len(solids)
            solids.append(solid)
            for fn in ends + sides:
                fp = '%s.faces["%s"]' % (sp, fn)
                fc = faces.get(fn, {})
                for k in fc:
                    if k not in FACE_KEYS:
                        rep.err(fp + "." + k, "unknown key")
                if "material" in fc:
                    use(fc["material"], fp + ".material")
                fmat = fc.get("material", s.get("material"))
                if fc.get("open", False):
                    if fc.get("holes"):
                        rep.err(fp + ".holes", "holes in an open face")
                    continue
                surfaces += 1
                fps = fc.get("patch_size", sps)
                # face geometry in its own 2-D coordinates
                if fn in ("top", "bottom"):
                    fpoly = solid.top_prof if fn == "top" else prof
                    area = abs(poly_area2(fpoly)) / 2
                elif solid.kind == "none":
                    n = int(fn.split()[1])
                    a, b = prof[n], prof[(n + 1) % len(prof)]
                    L = math.hypot(b[0] - a[0], b[1] - a[1])
                    fpoly = [[0, 0], [L, 0], [L, t - f], [0, t - f]]
                    area = L * (t - f)
                else:
                    fpoly = None
                    area = 0.0
                    if solid.geometric:
                        wp = solid.faces[fn]
                        area = _norm(newell(wp)) / 2
                holes = fc.get("holes", [])
                if not isinstance(holes, list):
                    rep.err(fp + ".holes", "not a list")
                    holes = []
                hpolys = []
                for hi, h in enumerate(holes):
                    hp = "%s.holes[%d]" % (fp, hi)
                    if not isinstance(h, dict):
                        rep.err(hp, "not an object")
                        continue
                    for k in h:
                        if k not in HOLE_KEYS:
                            rep.err(hp + "." + k, "unknown key")
                    poly = h.get("polygon")
                    if not (isinstance(poly, list) and all(_vec(p, 2) for p in poly)):
                        rep.err(hp + ".polygon", "needs a list of [a, b] points")
                        continue
                    prob = convexity_problem(poly, scale)
                    if prob:
                        rep.err(hp + ".polygon", prob + " (our rule: convex holes)")
                        continue
                    if fpoly is None or (solid.kind == "linear" and fn.startswith("side")):
                        rep.err(hp, "hole on a tapered side face (our rule: avoid)")
                        continue
                    for q in poly:
                        if not point_in_convex(q, fpoly, margin):
                            rep.err(hp + ".polygon", "point %s not strictly inside its face" % (q,))
                            break
                    for pj, other in hpolys:
                        if separation_2d(poly, other) <= margin:
                            rep.err(hp + ".polygon", "touches or overlaps hole %d" % pj)
                    hpolys.append((hi, poly))
                    area -= abs(poly_area2(poly)) / 2
                    if "fill" in h:
                        use(h["fill"], hp + ".fill")
                        surfaces += 1
                        harea = abs(poly_area2(poly)) / 2
                        patches += max(1, math.ceil(harea / (fps * fps)))
                        if solid.geometric:
                            m = solid.face_frame(fn)
                            wpoly = [m(q) for q in poly]
                            fills.append((wpoly, solid, hp, h["fill"]))
                            merge_faces.append((h["fill"], wpoly, solid, fn))
                patches += max(1, math.ceil(area / (fps * fps)))
                if solid.geometric:
                    merge_faces.append((fmat, solid.faces[fn], solid, fn))

    # --- materials all used -------------------------------------------------
    for name in mats:
        if name not in used:
            rep.err("materials." + name, "defined but never used (our rule)")

    # --- geometry: overlaps, containment -------------------------------------
    # Rooms are the inward solids not inside another inward solid; a nested
    # inward solid (a sink basin) is a piece of furniture like any other.
    geo = [s for s in solids if s.geometric]
    inward = [s for s in geo if s.inward]
    rooms = [s for s in inward
             if not any(r is not s and all(r.contains(v, -tol) for v in s.verts) for r in inward)]
    plain = [s for s in geo if s not in rooms]
    for s in solids:
        if not s.geometric:
            rep.note(s.path, "radial taper: geometry checks skipped")
    for i in range(len(plain)):
        a = plain[i]
        for j in range(i + 1, len(plain)):
            b = plain[j]
            if any(a.lo[k] >= b.hi[k] - tol or b.lo[k] >= a.hi[k] - tol for k in range(3)):
                continue
            pen = penetration(a.verts, a.normals.values(), a.edges,
                              b.verts, b.normals.values(), b.edges)
            if pen > tol:
                rep.err(a.path, "overlaps %s (%r) by %.4g" % (b.path, b.oname, pen))
    for s in plain:
        if not any(all(r.contains(v, -tol) for v in s.verts) for r in rooms):
            rep.err(s.path, "not inside any inward (room) solid")

    # fills touched over an area by other solids: allowed (mullions, knobs),
    # listed as notes.  The fill is shrunk a little so that a solid that only
    # meets its boundary (a window jamb) is not reported.
    for wpoly0, owner, hp, fill in fills:
        c = [sum(v[i] for v in wpoly0) / len(wpoly0) for i in range(3)]
        wpoly = [[c[i] + (v[i] - c[i]) * (1 - 1e-3) for i in range(3)] for v in wpoly0]
        nrm = _unit(newell(wpoly))
        edges = unique_dirs([_sub(wpoly[(i + 1) % len(wpoly)], wpoly[i]) for i in range(len(wpoly))])
        lo = [min(v[i] for v in wpoly) for i in range(3)]
        hi = [max(v[i] for v in wpoly) for i in range(3)]
        for s in plain:
            if s is owner:
                continue
            if any(s.lo[k] > hi[k] + tol or lo[k] > s.hi[k] + tol for k in range(3)):
                continue
            pen = penetration(s.verts, s.normals.values(), s.edges, wpoly, [nrm], edges)
            if pen >= -tol:
                rep.note(hp, "fill %r is touched by %s (%r)" % (fill, s.path, s.oname))

    # --- cameras --------------------------------------------------------------
    cams = doc.get("cameras", {})
    if not isinstance(cams, dict) or "default" not in cams:
        rep.err("cameras", "needs a camera named default")
        cams = cams if isinstance(cams, dict) else {}
    for cname, c in cams.items():
        cp = "cameras.%s" % cname
        if not isinstance(c, dict):
            rep.err(cp, "not an object")
            continue
        for k in c:
            if k not in CAMERA_KEYS:
                rep.err(cp + "." + k, "unknown key")
        p, la, up = c.get("position"), c.get("look_at"), c.get("up", [0, 1, 0])
        fov = c.get("fov_y", 60)
        if not (_vec(p, 3) and _vec(la, 3) and _vec(up, 3)):
            rep.err(cp, "position, look_at and up need 3 numbers")
            continue
        if not (_isnum(fov) and 0 < fov < 180):
            rep.err(cp + ".fov_y", "needs 0 < fov_y < 180")
        d = _sub(la, p)
        if _norm(d) == 0 or _norm(_cross(d, up)) <= 1e-9 * _norm(d) * _norm(up):
            rep.err(cp, "view direction zero or parallel to up")
        if rooms and not any(r.contains(p, 1e-3 * scale) for r in rooms):
            # looking into an open room from outside (a Cornell box) is fine
            if any(f.get("open") for r in rooms for f in r.raw.get("faces", {}).values()):
                rep.note(cp + ".position", "outside the (open) room")
            else:
                rep.err(cp + ".position", "not inside a closed room")
        for s in plain:
            if s.contains(p, -tol):
                rep.err(cp + ".position", "inside %s (%r)" % (s.path, s.oname))

    for fa, fb in coplanar_overlaps(merge_faces, tol):
        rep.err(fa, "overlaps %s in the same plane, facing the same way" % fb)
    merged = estimate_merged(merge_faces, tol)
    if describe:
        describe_scene(doc, solids, fills, rep)
    return rep, (surfaces, merged, patches, ps_default, units)


def _plane_groups(faces, tol, with_material):
    """Group surfaces by (material,) plane and facing; also returns 2-D
    coordinates of each polygon in its plane."""
    groups = {}
    for idx, (m, poly, solid, fn) in enumerate(faces):
        nrm = _unit(newell(poly))
        if nrm is None:
            continue
        if fn in solid.normals:
            out = solid.normals[fn]
            if solid.inward:
                out = [-e for e in out]
            if _dot(nrm, out) < 0:
                nrm = [-e for e in nrm]
        off = _dot(nrm, poly[0])
        key = (tuple(round(e, 6) for e in nrm), round(off / (tol * 1000)))
        if with_material:
            key = (m,) + key
        groups.setdefault(key, []).append(idx)
    out = []
    for key, idxs in groups.items():
        nrm = key[-2]
        ref = [1.0, 0.0, 0.0] if abs(nrm[0]) < 0.9 else [0.0, 1.0, 0.0]
        e1 = _unit(_cross(nrm, ref))
        e2 = _cross(nrm, e1)
        p2 = {i: [[_dot(v, e1), _dot(v, e2)] for v in faces[i][1]] for i in idxs}
        out.append((idxs, p2))
    return out


def coplanar_overlaps(faces, tol):
    """Pairs of surfaces of different faces that share a plane and a facing
    and overlap with positive area (they would fight in the z-buffer and
    be counted twice by the solver)."""
    bad = []
    for idxs, p2 in _plane_groups(faces, tol, False):
        for a in range(len(idxs)):
            for b in range(a + 1, len(idxs)):
                i, j = idxs[a], idxs[b]
                si, sj = faces[i][2], faces[j][2]
                if si is sj and faces[i][3] == faces[j][3]:
                    continue  # a face and the fill of one of its holes
                if separation_2d(p2[i], p2[j]) < -tol:
                    bad.append(('%s.faces["%s"]' % (si.path, faces[i][3]),
                                '%s.faces["%s"] (%r)' % (sj.path, faces[j][3], sj.oname)))
    return bad


def estimate_merged(faces, tol):
    """Surfaces left if coplanar, same-facing, touching faces of one material
    were merged (what the preprocessor may do): union-find per plane."""
    total = 0
    for idxs, p2 in _plane_groups(faces, tol, True):
        parent = {i: i for i in idxs}

        def find(i):
            while parent[i] != i:
                parent[i] = parent[parent[i]]
                i = parent[i]
            return i
        for a in range(len(idxs)):
            for b in range(a + 1, len(idxs)):
                i, j = idxs[a], idxs[b]
                if separation_2d(p2[i], p2[j]) <= tol:
                    parent[find(i)] = find(j)
        total += len({find(i) for i in idxs})
    return total


def describe_scene(doc, solids, fills, rep):
    print("== %s" % rep.fname)
    by_obj = {}
    for s in solids:
        by_obj.setdefault(s.oi, []).append(s)
    for oi, o in enumerate(doc.get("objects", [])):
        ss = [s for s in by_obj.get(oi, []) if s.geometric]
        if not ss:
            continue
        lo = [min(s.lo[k] for s in ss) for k in range(3)]
        hi = [max(s.hi[k] for s in ss) for k in range(3)]
        print("  object %-26r solids %3d  x %7.2f..%-7.2f y %7.2f..%-7.2f z %7.2f..%-7.2f" % (
            o.get("name"), len(o.get("solids", [])), lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]))
    for wpoly, owner, _, fill in fills:
        lo = [min(v[k] for v in wpoly) for k in range(3)]
        hi = [max(v[k] for v in wpoly) for k in range(3)]
        print("  fill %-22r on %r: x %.2f..%.2f y %.2f..%.2f z %.2f..%.2f" % (
            fill, owner.oname, lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]))
    for cname, c in doc.get("cameras", {}).items():
        print("  camera %-14r at %s looking at %s fov_y %s" % (cname, c["position"], c["look_at"], c.get("fov_y")))
    for n in rep.notes:
        print("  note: " + n)


def run_checks(paths, describe=False):
    ok = True
    for path in paths:
        rep, info = check_scene(path, describe)
        fname = os.path.basename(path)
        for e in rep.errors:
            print("ERROR " + e)
        if rep.errors:
            ok = False
            print("%s: FAILED (%d errors)" % (fname, len(rep.errors)))
            continue
        surfaces, merged, patches, ps, units = info
        need = MIN_SURFACES.get(fname, 0) if os.path.dirname(os.path.abspath(path)) == ASSETS else 0
        status = "ok"
        if surfaces < need:
            status = "FAILED (needs at least %d surfaces)" % need
            ok = False
        print("%s: %s: %d surfaces (%d after merging coplanar touching faces of one material), "
              "~%d patches at patch_size %g %s" % (fname, status, surfaces, merged, patches, ps, units))
    return ok


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", nargs="*", metavar="SCENE",
                    help="only check (the generated files, or the given scene files)")
    ap.add_argument("--describe", action="store_true",
                    help="also print objects, filled holes and cameras in world space")
    args = ap.parse_args(argv)
    if args.check is not None and args.check:
        paths = args.check
    else:
        paths = [os.path.join(ASSETS, f) for f, _ in SCENES]
        if args.check is None:
            for (_, build), path in zip(SCENES, paths):
                text = to_json(build())
                with open(path, "w") as fh:
                    fh.write(text)
                print("wrote %s" % os.path.relpath(path))
    return 0 if run_checks(paths, args.describe) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
