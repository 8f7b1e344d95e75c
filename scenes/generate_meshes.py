#!/usr/bin/python3
# Generates the OBJ meshes the aliaslab scenes use, into scenes/meshes/.
#
# Run from anywhere with the system Python (standard library only):
#     /usr/bin/python3 scenes/generate_meshes.py
# The output is deterministic (no randomness, fixed number formatting), so
# rerunning it reproduces the committed .obj files byte for byte.
#
# Meshes (every face counter-clockwise seen from outside):
#   vase.obj   a lathed vase with a rolled lip and an inner wall (3,968 triangles)
#   knot.obj   a (2,3) torus-knot tube (4,608 triangles)
#   cube.obj   the unit cube [-0.5, 0.5]^3 (12 triangles)
#   gem.obj    a round brilliant: table, star, kite and upper-girdle facets,
#              girdle band, pavilion mains and lower-girdle facets (112 triangles)
#   fence.obj  a picket fence: 48 posts of shrinking width and two rails (600 triangles)
import math
import os

OUT_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "meshes")


class Mesh:
    def __init__(self, comment):
        self.comment = comment
        self.vertices = []
        self.faces = []

    def vertex(self, p):
        self.vertices.append(p)
        return len(self.vertices) - 1

    def tri(self, a, b, c):
        self.faces.append((a, b, c))

    def orient_outward(self, centre):
        """Flips faces whose normal points towards `centre` (star-shaped solids)."""
        v = self.vertices
        for i, (a, b, c) in enumerate(self.faces):
            e1 = [v[b][j] - v[a][j] for j in range(3)]
            e2 = [v[c][j] - v[a][j] for j in range(3)]
            n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
            out = sum(n[j] * (v[a][j] + v[b][j] + v[c][j] - 3 * centre[j]) for j in range(3))
            if out < 0:
                self.faces[i] = (a, c, b)

    def quad(self, a, b, c, d):
        self.tri(a, b, c)
        self.tri(a, c, d)

    def write(self, name):
        path = os.path.join(OUT_DIR, name)
        with open(path, "w", newline="\n") as f:
            f.write(f"# {self.comment}\n# written by scenes/generate_meshes.py; do not edit\n")
            f.write(f"# {len(self.vertices)} vertices, {len(self.faces)} triangles\n")
            for x, y, z in self.vertices:
                f.write(f"v {fmt(x)} {fmt(y)} {fmt(z)}\n")
            for a, b, c in self.faces:
                f.write(f"f {a + 1} {b + 1} {c + 1}\n")
        print(f"{path}: {len(self.faces)} triangles")


def fmt(x):
    s = f"{x:.6f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


# Lathe -----------------------------------------------------------------------
def lathe(mesh, profile, segments):
    """Revolves (r, y) profile points about the y axis. Points with r == 0 are
    poles (one vertex). The profile runs from the bottom pole up the outside;
    faces are then counter-clockwise seen from outside."""
    rings = []
    for r, y in profile:
        if r == 0.0:
            rings.append([mesh.vertex((0.0, y, 0.0))])
        else:
            ring = []
            for k in range(segments):
                a = 2.0 * math.pi * k / segments
                ring.append(mesh.vertex((r * math.cos(a), y, -r * math.sin(a))))
            rings.append(ring)
    for lo, hi in zip(rings, rings[1:]):
        for k in range(segments):
            k1 = (k + 1) % segments
            if len(lo) == 1:
                mesh.tri(lo[0], hi[k1], hi[k])
            elif len(hi) == 1:
                mesh.tri(lo[k], lo[k1], hi[0])
            else:
                mesh.quad(lo[k], lo[k1], hi[k1], hi[k])


def vase():
    mesh = Mesh("lathed vase, base on y = 0, height 2, radius <= 0.8")
    outside = []
    n_out = 22
    for i in range(n_out + 1):
        t = i / n_out
        y = 0.04 + 1.84 * t
        r = 0.42 + 0.36 * math.sin(math.pi * min(1.0, t / 0.8)) ** 1.5 - 0.2 * t + 0.14 * t ** 6
        outside.append((r, y))
    rim_r = outside[-1][0]
    lip = [(rim_r + 0.04, 1.92), (rim_r + 0.02, 1.98), (rim_r - 0.04, 1.99), (rim_r - 0.07, 1.94)]
    inside = [(rim_r - 0.09, 1.8), (rim_r - 0.11, 1.6), (rim_r - 0.1, 1.4)]
    profile = [(0.0, 0.0), (0.36, 0.0)] + outside + lip + inside + [(0.0, 1.4)]
    lathe(mesh, profile, 64)
    return mesh


# Torus knot --------------------------------------------------------------------
def knot(p=2, q=3, along=192, around=12, tube=0.28):
    mesh = Mesh(f"({p},{q}) torus knot tube, radius about 1.5, tube radius {tube}")

    def curve(t):
        r = 1.0 + 0.5 * math.cos(q * t)
        return (r * math.cos(p * t), 0.5 * math.sin(q * t), r * math.sin(p * t))

    def sub(a, b):
        return tuple(x - y for x, y in zip(a, b))

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def unit(a):
        n = math.sqrt(sum(x * x for x in a))
        return tuple(x / n for x in a)

    rings = []
    for i in range(along):
        t = 2.0 * math.pi * i / along
        c = curve(t)
        tangent = unit(sub(curve(t + 1e-4), curve(t - 1e-4)))
        normal = unit(cross(tangent, (0.0, 1.0, 0.0)))
        binormal = cross(normal, tangent)
        ring = []
        for k in range(around):
            a = 2.0 * math.pi * k / around
            ring.append(mesh.vertex(tuple(c[j] + tube * (math.cos(a) * normal[j] + math.sin(a) * binormal[j])
                                          for j in range(3))))
        rings.append(ring)
    for i in range(along):
        lo, hi = rings[i], rings[(i + 1) % along]
        for k in range(around):
            k1 = (k + 1) % around
            mesh.quad(lo[k], hi[k], hi[k1], lo[k1])
    return mesh


# Boxes -------------------------------------------------------------------------
def box(mesh, lo, hi):
    v = [mesh.vertex((hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]))
         for i in range(8)]
    mesh.quad(v[0], v[2], v[3], v[1])  # -z
    mesh.quad(v[4], v[5], v[7], v[6])  # +z
    mesh.quad(v[0], v[4], v[6], v[2])  # -x
    mesh.quad(v[1], v[3], v[7], v[5])  # +x
    mesh.quad(v[0], v[1], v[5], v[4])  # -y
    mesh.quad(v[2], v[6], v[7], v[3])  # +y


def cube():
    mesh = Mesh("unit cube [-0.5, 0.5]^3")
    box(mesh, (-0.5, -0.5, -0.5), (0.5, 0.5, 0.5))
    return mesh


def fence(posts=48, spacing=0.125, width=0.06, shrink=0.93, height=2.0):
    """Posts along +x from x = 0, each `shrink` times as wide as the one before
    (0.06 down to about 0.002 units), and two rails behind them."""
    mesh = Mesh(f"picket fence: {posts} posts every {spacing} along +x, widths {width} * {shrink}^i, two rails")
    for i in range(posts):
        x, w = i * spacing, width * shrink ** i
        box(mesh, (x - w / 2, 0.0, -w / 2), (x + w / 2, height, w / 2))
    length = (posts - 1) * spacing
    for y, h in ((0.5, 0.03), (1.5, 0.008)):
        box(mesh, (-0.1, y - h / 2, -0.05), (length + 0.1, y + h / 2, -0.04))
    return mesh


# Round brilliant -------------------------------------------------------------
def gem():
    """Girdle radius 1 in the xz plane; crown up (+y), pavilion down."""
    mesh = Mesh("round brilliant: 8-fold crown and pavilion, 16-sided girdle")
    # Tolkowsky-like proportions, as fractions of the girdle radius 1
    g_half = 0.03                  # half the girdle thickness
    crown_h, table_r = 0.3, 0.56   # crown height above the girdle (34.5 degrees), table radius
    star_r, star_h = 0.78, 0.15    # star-facet tips: radius, height above the girdle
    pav_d, lower_r = 0.86, 0.25    # pavilion depth (40.75 degrees); lower-girdle facet tips radius

    def polar(r, angle_deg, y):
        a = math.radians(angle_deg)
        return mesh.vertex((r * math.cos(a), y, -r * math.sin(a)))

    top = g_half + crown_h
    centre = mesh.vertex((0.0, top, 0.0))
    table = [polar(table_r, 45 * k, top) for k in range(8)]
    star = [polar(star_r, 45 * k + 22.5, g_half + star_h) for k in range(8)]
    girdle_top = [polar(1.0, 22.5 * m, g_half) for m in range(16)]
    girdle_bot = [polar(1.0, 22.5 * m, -g_half) for m in range(16)]
    lower = [polar(lower_r, 45 * k + 22.5, -g_half - pav_d * (1 - lower_r)) for k in range(8)]
    culet = mesh.vertex((0.0, -g_half - pav_d, 0.0))
    for k in range(8):
        k1 = (k + 1) % 8
        mesh.tri(centre, table[k], table[k1])                            # table
        mesh.tri(table[k], star[k], table[k1])                           # star facet
        mesh.quad(table[k], star[k - 1], girdle_top[2 * k], star[k])     # kite (bezel)
        mesh.tri(star[k], girdle_top[2 * k], girdle_top[2 * k + 1])      # upper girdle
        mesh.tri(star[k], girdle_top[2 * k + 1], girdle_top[(2 * k + 2) % 16])
        mesh.quad(culet, lower[k], girdle_bot[2 * k1 % 16], lower[k1])   # pavilion main
        mesh.tri(lower[k], girdle_bot[2 * k + 1], girdle_bot[(2 * k + 2) % 16])  # lower girdle
        mesh.tri(lower[k], girdle_bot[2 * k], girdle_bot[2 * k + 1])
    for m in range(16):                                                  # girdle band
        m1 = (m + 1) % 16
        mesh.quad(girdle_bot[m], girdle_bot[m1], girdle_top[m1], girdle_top[m])
    mesh.orient_outward((0.0, -0.1, 0.0))
    return mesh


if __name__ == "__main__":
    os.makedirs(OUT_DIR, exist_ok=True)
    vase().write("vase.obj")
    knot().write("knot.obj")
    cube().write("cube.obj")
    gem().write("gem.obj")
    fence().write("fence.obj")
