"""Reference model of the master's second segment method (firmware/master/master.asm, SMP...):
Watanabe and Iwai's sampling interpolation (IECI '81, section 2, eqs. 2-7), worked on the host in
the same integer arithmetic the 8085 does, from the paper and docs/contours.md, not from the
emulator. It predicts every sample's output: the pulses per axis (-1, 0, +1) the sample sends.

Numbers (docs/contours.md, "Sampling"): single precision B = 16 bits, double precision 32 bits
(16.16, dX' = 2^-16 step), C_L = 8, so a segment is X_d = 2^(B-1-C_L) = 128 steps of the major
axis and x_r fits one byte; M = 15 (the X travel, 30000 steps < 2^15).

One chord (a line, or one 2^-C_R chord of an arc between exact 16.16 vertices A and E), the tool's
target P (whole steps) where the previous chord left it:
  u: the axis with the larger |E - A| (x in the paper's Fig. 3), v the other;
  n = |round(E_u) - P_u| whole steps of u, su their direction;
  Q = floor(2^24 V / U) (V = |dv|, U = |du|, both brought below 2^15 first: div24), T_y = min(FFFFH, (Q + 80H) >> 8) (0.16),
  Y_d* = (Q + 1) >> 1 (128 T exact to 2^-17: the projection of a segment, double precision);
  sigma: the v direction as u goes su; Y0* = sigma (A_v - P_v) + T_y . su (P_u - A_u): the first
  point corrected (eq. 13: -(X* - X#) T_y + Y* - Y#), 16.16;
  segment i = k >> 7: Y_i* = Y0* + i Y_d*; y0* = frac(Y_i*) + 1/2 (eq. 3);
  sample: k* += dS_x (eq. 4), k = min(n, floor k*), x_r = k & 127,
          w = floor(Y_i*) + floor(T_y x_r + y0*) (eq. 5), target = P + (su k, sigma w);
  the chord ends in the sample that reaches k = n; k* - n carries into the next chord.
Each sample sends at most one pulse per axis, both in one OUT (eq. 6's dx_s, dy_s): the output
follows the target by -1, 0 or +1 per axis (a target more than a step away, which only a chord's
first point can ask, is reached in the next sample).

Timing: phases[] holds, per sample,
the T-states after the sample's tick at which x* crossed its step, 24 (255 - floor(256 r / dS_x))
with r = frac(k*) after the sample's dS_x (0 <= r < dS_x: the crossing lies (dS_x - r) / dS_x into
the sample; PERIOD / 256 = 24), where k* passed a whole step; 0 where it did not. The master sends
the sample's pulses (both axes in one OUT) then, not at the tick: the major axis's pulses come
1 / rate apart to 24 T-states, not on the 2 ms grid.

Feed (per sample, before the progress): f path steps per sample (0.16), dS_x = (f C_x) >> 16 with
C_x = CXTAB[T_y >> 12] (16 entries, the cosine at the middle of each interval: eq. 4's C_x). With
the ramp, the group starts at F_MIN (or F_s if lower) and each sample either decelerates (L_rem <= D, the distance the
deceleration down the levels it came up would need), or accelerates by A_F up to the group's F_s;
L_rem -= f. Without it f = F_s from the first sample to the last.
"""
import math

import contour_ref as ref

PERIOD = 6144            # T-states: 2 ms at 3.072 MHz, the paper's sampling period
F_MIN = 0x8000           # 0.5 step a sample = 250 steps/s: start and stop, below the motor's 405
A_F = 328                # 0.16 steps/sample^2 = 1250 steps/s^2: 250 -> 500 steps/s in 100 samples (0.2 s)
DWELL = 20               # samples at rest at a stop point (40 ms)
HEADER = 5               # path-table type of a sampling group's header
CL = 8
XD = 1 << (16 - 1 - CL)  # 128

CXTAB = [min(0xFFFF, round(65536 / math.sqrt(1 + ((i + 0.5) / 16) ** 2))) for i in range(16)]


def sgn(v):
    return -1 if v < 0 else 1


def div24(v, u):
    """floor(2^24 v / u) as the 8085 does it (SDIV): U and V (16.16) brought below 2^15 together
    (whole-step values straight from their high words, else shifted right), V = U gives 2^24, else
    24 steps of restoring division with the remainder in HL."""
    if (u & 0xFFFF) == 0 and (v & 0xFFFF) == 0:
        u, v = u >> 16, v >> 16
    while u >= 1 << 15:
        u, v = u >> 1, v >> 1
    if v == u:
        return 1 << 24
    q, r = 0, v
    for _ in range(24):
        r <<= 1
        q <<= 1
        if r >= u:
            r -= u
            q |= 1
    return q


class Chord:
    def __init__(self, a, e, p):
        """a, e: (x, y) 16.16 absolute; p: the tool's target (x, y) in steps."""
        dx, dy = e[0] - a[0], e[1] - a[1]
        self.mu = 0 if abs(dx) >= abs(dy) else 1
        mu, mv = self.mu, 1 - self.mu
        du, dv = (dx, dy) if mu == 0 else (dy, dx)
        eu = (e[mu] + 0x8000) >> 16
        self.su = 1 if eu >= p[mu] else -1
        self.n = abs(eu - p[mu])
        U, V = abs(du), abs(dv)
        q = div24(V, U) if U else 0
        self.t = min(0xFFFF, (q + 0x80) >> 8)
        self.yd = (q + 1) >> 1
        self.sigma = sgn(dv) * sgn(du) * self.su if dv else 1
        off = self.su * ((p[mu] << 16) - a[mu])
        assert abs(off) < 1 << 24, "a chord starts more than 256 steps from the tool"
        toff = (self.t * abs(off)) >> 16
        self.y0 = self.sigma * (a[mv] - (p[mv] << 16)) + (toff if off >= 0 else -toff)
        self.p = p
        self.cx = CXTAB[self.t >> 12]

    def target(self, k):
        i, xr = k >> 7, k & (XD - 1)
        yi = self.y0 + i * self.yd
        w = (yi >> 16) + ((self.t * xr + (yi & 0xFFFF) + 0x8000) >> 16)
        t = [0, 0]
        t[self.mu] = self.p[self.mu] + self.su * k
        t[1 - self.mu] = self.p[1 - self.mu] + self.sigma * w
        return tuple(t)


def chords_of(e, start, tp):
    """The chords of one entry as (A, E) pairs of 16.16 points; the tool's target tp for the first."""
    if e["kind"] in (3, 4):
        pts = ref.polygon_fixed(e, start)
    else:
        pts = [(start[0] << 16, start[1] << 16), (e["x"] << 16, e["y"] << 16)]
    return list(zip(pts, pts[1:]))


class Run:
    """One sampling path on the host: samples[] = (dx, dy) per sample, in order."""

    def __init__(self, path):
        self.samples = []
        self.targets = []
        self.phases = []
        self.joins = set()       # each chord's first sample
        self.out = [0, 0]
        self.z = 0
        self.stops = 0
        self.k = 0
        first = True
        pos = (0, 0)
        self.tp = (0, 0)
        for e in path:
            if e["kind"] == HEADER:
                self.stop()
                self.ramp = bool(e["cr"] & 1)
                self.fs = e["feed"]
                self.lrem = (e["y"] << 16) | e["x"]
                if self.lrem >= 1 << 31:
                    self.lrem -= 1 << 32
                self.f = min(F_MIN, self.fs) if self.ramp else self.fs
                self.j = 0
                self.d = 0
                self.k = 0
                continue
            if e["z"] != self.z:
                self.z = e["z"]
            for a, b in chords_of(e, pos, self.tp):
                self.chord(Chord(a, b, self.tp))
            pos = (e["x"], e["y"])
        self.stop()

    def level(self):
        return min(self.fs, F_MIN + self.j * A_F)

    def chord(self, c):
        self.joins.add(len(self.samples))
        while True:
            if self.ramp:
                if self.lrem <= self.d:
                    if self.j > 0:
                        self.d -= self.f
                        self.j -= 1
                        self.f = self.level()
                elif self.f < self.fs:
                    self.j += 1
                    self.f = self.level()
                    self.d += self.f
            self.lrem -= self.f
            ds = (self.f * c.cx) >> 16
            k0 = self.k >> 16
            self.k += ds
            kr = self.k >> 16
            r = self.k & 0xFFFF
            phase = 24 * (255 - (r << 8) // ds) if kr > k0 else 0
            done = kr >= c.n
            if done:
                kr = c.n
                self.k -= c.n << 16
            t = c.target(kr)
            self.emit(t, phase)
            if done:
                self.tp = t
                return

    def emit(self, t, phase=0):
        self.phases.append(phase)
        d = [max(-1, min(1, t[i] - self.out[i])) for i in (0, 1)]
        self.out = [self.out[0] + d[0], self.out[1] + d[1]]
        self.samples.append((d[0], d[1]))
        self.targets.append(t)

    def stop(self):
        """A stop point (every header, and the path's end): the output catches up with the target,
        then DWELL samples at rest, and one more (the sample before the next chord's first, whose
        output the 8085 sends one tick after it computes it)."""
        while tuple(self.out) != self.tp:
            self.emit(self.tp)
        for _ in range(DWELL + 1):
            self.emit(self.tp)
        self.stops += 1


def eps_l7(dx, dy, m=15, b=16, cl=CL):
    """eq. 7: C_x (2^(2M - 3B + 2 + C_L) + 2^(-C_L - 1) + 2^-1) steps."""
    h = math.hypot(dx, dy)
    cx = max(abs(dx), abs(dy)) / h if h else 1.0
    return cx * (2.0 ** (2 * m - 3 * b + 2 + cl) + 2.0 ** (-cl - 1) + 0.5)
