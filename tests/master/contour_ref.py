"""Reference model of firmware/master/master.asm, worked from Watanabe and Iwai (IECI '81) and
the path-table layout of docs/contours.md, not from the emulator: it predicts every segment the
master hands to the thesis line routine, and the paper's bounds for each move.

  eq. 8-11: the centre angle of a segment is 2^-C_R rad; X*, Y* are 16.16 (dX' = 2^-16 step);
            each shift adds half its last place first (the paper's 2^(C_R+1) dX' ... terms),
            rsh(v, n) = (v + 2^(n-1)) >> n, floor shifts as the 8085's RAR with the sign in CY.
  eq. 9:    eps_A = 2^(-2 C_R - 4) R; the first point is pushed out by eps_A: S + rsh(S, 2 C_R + 4).
  eq. 7:    eps_L,max = C_x (2^(2M - 3B + 2 + C_L) + 2^(-C_L - 1) + 2^-1) dX, here B = 16 (the
            slope is 16.16), C_L = 0 (the thesis draws a line in one piece), M = bits of the longest
            projection.
"""
import math

TABLE = 0x3DD0
ENTRY = 16


def read_hex(path):
    mem = {}
    for line in open(path):
        line = line.strip()
        if not line.startswith(":"):
            continue
        b = bytes.fromhex(line[1:])
        n, addr, kind = b[0], (b[1] << 8) | b[2], b[3]
        if kind == 0:
            for i in range(n):
                mem[addr + i] = b[4 + i]
    return mem


def paths(mem):
    """The table's paths: lists of entries (dicts), as the master reads them."""
    out, cur, a = [], [], TABLE
    while a in mem:
        e = [mem.get(a + i, 0xFF) for i in range(ENTRY)]
        w = lambda k: e[k] | (e[k + 1] << 8)
        if e[0] == 0:
            out.append(cur)
            cur = []
        else:
            cur.append(dict(kind=e[0], cr=e[1], feed=w(2), x=w(4), y=w(6), z=w(8), cx=w(10), cy=w(12), n=w(14)))
        a += ENTRY
    return out


def rsh(v, n):
    return ((v >> (n - 1)) + 1) >> 1


def step3(p, q, sigma, k):
    t = rsh(q, k + 2)
    t = p + sigma * t
    t = rsh(t, k + 1)
    t = q - sigma * t
    t = rsh(t, k)
    return p + sigma * t


def rnd(v):
    return (v + 0x8000) >> 16


def rnd_x(ax, ay, s):
    """X* to a step against the X motion at the vertex (docs/contours.md, "Rounding against the
    staircase"): the floor where X goes + (CCW below the centre, CW above it), else the ceiling."""
    going_plus = (ay < 0) if s == 1 else (ay >= 0)
    return ax >> 16 if going_plus else -((-ax) >> 16)


def handoffs(path, nearest=False):
    """Every hand-over in order: ('Z', z) or ('XY', x2, y2, entry index); the table starts at 0, 0, 0.
    nearest: X* rounded to the nearest step too, as the master did before (docs/contours.md's table)."""
    x = y = z = 0
    out = []
    for i, e in enumerate(path):
        if e["z"] != z:
            z = e["z"]
            out.append(("Z", z, None, i))
        pts = []
        if e["kind"] in (3, 4):
            k, s = e["cr"], (1 if e["kind"] == 4 else -1)
            ax = (x - e["cx"]) << 16
            ay = (y - e["cy"]) << 16
            ax += rsh(ax, 2 * k + 4)
            ay += rsh(ay, 2 * k + 4)
            for _ in range(e["n"]):
                ax, ay = step3(ax, ay, -s, k), step3(ay, ax, s, k)
                pts.append((e["cx"] + (rnd(ax) if nearest else rnd_x(ax, ay, s)), e["cy"] + rnd(ay)))
        pts.append((e["x"], e["y"]))
        for px, py in pts:
            if (px, py) != (x, y):
                out.append(("XY", px, py, i))
                x, y = px, py
    return out


def polygon(e, start):
    """The arc's unrounded vertices (steps, from the 16.16 values), first-point correction included,
    then the exact end point: the polygon eq. 9 speaks of."""
    k, s = e["cr"], (1 if e["kind"] == 4 else -1)
    ax = (start[0] - e["cx"]) << 16
    ay = (start[1] - e["cy"]) << 16
    ax += rsh(ax, 2 * k + 4)
    ay += rsh(ay, 2 * k + 4)
    pts = [(float(start[0]), float(start[1]))]
    for _ in range(e["n"]):
        ax, ay = step3(ax, ay, -s, k), step3(ay, ax, s, k)
        pts.append((e["cx"] + ax / 65536.0, e["cy"] + ay / 65536.0))
    pts.append((float(e["x"]), float(e["y"])))
    return pts


def polygon_fixed(e, start):
    """The same polygon as 16.16 absolute coordinates (the sampling method's chords run between
    these exact vertices): the start, each vertex, the end."""
    k, s = e["cr"], (1 if e["kind"] == 4 else -1)
    ax = (start[0] - e["cx"]) << 16
    ay = (start[1] - e["cy"]) << 16
    ax += rsh(ax, 2 * k + 4)
    ay += rsh(ay, 2 * k + 4)
    pts = [(start[0] << 16, start[1] << 16)]
    for _ in range(e["n"]):
        ax, ay = step3(ax, ay, -s, k), step3(ay, ax, s, k)
        pts.append(((e["cx"] << 16) + ax, (e["cy"] << 16) + ay))
    pts.append((e["x"] << 16, e["y"] << 16))
    return pts


def polygon_error(e, start, r):
    """Largest distance of that polygon from the circle (at vertices and chord middles): over the
    inner chords (between corrected vertices: eq. 9 says eps_A), and over the first and last chord,
    which join a corrected vertex (R + eps_A) to a point on the circle (about 1.5 eps_A)."""
    c = (e["cx"], e["cy"])
    pts = polygon(e, start)
    off = lambda p: abs(math.hypot(p[0] - c[0], p[1] - c[1]) - r)
    chords = list(zip(pts, pts[1:]))
    worst = [0.0, 0.0]
    for i, (a, b) in enumerate(chords):
        end = i == 0 or i == len(chords) - 1
        mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        worst[end] = max(worst[end], off(mid), off(b) if i < len(chords) - 1 else 0.0)
    return worst[0], worst[1]


def staircase(dx, dy):
    """The thesis line rule's own bound (docs/contours.md): it steps one axis at a time and its YID
    is within one step of the line, so a point stands less than |slope| + 1 steps off in Y:
    (cos a + sin a) steps from the line, at most sqrt 2."""
    h = math.hypot(dx, dy)
    return 0.0 if h == 0 else (abs(dx) + abs(dy)) / h


def radius(e, start):
    return math.hypot(start[0] - e["cx"], start[1] - e["cy"])


def eps_a(cr, r):
    return r * 2.0 ** (-2 * cr - 4)


def eps_l(dx, dy):
    """eq. 7 with B = 16, C_L = 0: C_x (2^(2M-46) + 1/2 + 1/2) steps."""
    big = max(abs(dx), abs(dy))
    if big == 0:
        return 0.0
    m = big.bit_length()
    cx = big / math.hypot(dx, dy)
    return cx * (2.0 ** (2 * m - 46) + 0.5 + 0.5)
