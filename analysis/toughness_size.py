#!/usr/bin/env python3
"""The fracture toughness's size effect (issue 37 item 1): is K_IC of a DEM glass independent of the specimen, and
if not, what is its large-specimen (LEFM) limit?

    python3 analysis/toughness_size.py [RECORD.csv] [--out DIR]

RECORD (default data/studies/results/toughness_size.csv) is what `kerf-dem study data/studies/toughness_size.json`
writes: one row per beam, beam_depth_W_mm, notch_ratio_a_over_W, seed, fracture_toughness_MPa_sqrt_m,
fracture_energy_J_per_m2, ... Everything comes from the record alone.

Method: Bazant's size-effect law for geometrically similar specimens, sigma_N = B f_t / sqrt(1 + W / W_0), written
for the apparent toughness K(W) = P_max S / (B W^1.5) f(a/W) (proportional to sigma_N sqrt(W)):

    K(W) = K_inf / sqrt(1 + W_0 / W)      i.e.      1 / K^2 = A + C / W,  K_inf = A^-1/2,  W_0 = C / A

(Bazant & Kazemi 1990, "Determination of fracture energy, process zone length and brittleness number from size
effect", Int. J. Fracture 44, 111-131; the RILEM size-effect method of 1990 regresses the same line). K_inf is the
toughness of an infinitely large specimen, the LEFM K_IC; W_0 the transitional size, of the order of the process
zone (it depends on a/W, K_inf does not). The line is fitted by least squares over every beam (packings are the
replicates): per a/W, and jointly with one A and a C per a/W. Standard errors from the fit's covariance; the 95 %
interval of K_inf maps A's Student-t interval through A^-1/2 (unbounded above when it reaches A <= 0). K(W) is
within 10 % of K_inf for W >= W_0 / (1 / 0.9^2 - 1) = 4.26 W_0.

Writes DIR/size_effect.csv (per size and a/W: mean K and its standard error; per fit: K_inf, its interval, W_0,
the size from which K is within 10 % of K_inf) and DIR/size_effect.png (K against W with the fits), and prints
a Markdown summary.
"""
import argparse
import collections
import csv
import math
import pathlib
import statistics

import numpy as np

from kerf.result_keys import ToughnessResults as T
from kerf.stats import mean_of, t95 as student_t

WITHIN = 0.9  # K(W) / K_inf from which the toughness counts as size-independent


def read_record(path):
    """Rows as dicts with W (mm), a/W, seed, K (MPa sqrt(m)), G_c (J/m^2)."""
    rows = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            rows.append({"W": float(r["beam_depth_W_mm"]), "aW": float(r["notch_ratio_a_over_W"]),
                         "seed": int(r["seed"]), "K": float(r[T.fracture_toughness_MPa_sqrt_m]),
                         "G": float(r[T.fracture_energy_J_per_m2])})
    return rows


def by_size(rows):
    """(a/W, W) -> (n, mean K, standard error of K, mean G_c)."""
    groups = collections.defaultdict(list)
    for r in rows:
        groups[(r["aW"], r["W"])].append(r)
    out = {}
    for key, g in sorted(groups.items()):
        k = mean_of([r["K"] for r in g])
        out[key] = (k.n, k.value, k.se, statistics.fmean(r["G"] for r in g))
    return out


class Fit:
    """1 / K^2 = A + C_j / W by least squares; one A, a C per notch ratio j."""

    def __init__(self, rows):
        ratios = sorted({r["aW"] for r in rows})
        self.ratios = ratios
        x = np.array([[1.0] + [1.0 / r["W"] if r["aW"] == j else 0.0 for j in ratios] for r in rows])
        y = np.array([1.0 / r["K"] ** 2 for r in rows])
        self.n, self.p = x.shape
        self.dof = self.n - self.p
        if self.dof < 1 or np.linalg.matrix_rank(x) < self.p:
            raise ValueError("too few beams or sizes to fit the size-effect law")
        beta, *_ = np.linalg.lstsq(x, y, rcond=None)
        resid = y - x @ beta
        s2 = float(resid @ resid) / self.dof
        cov = s2 * np.linalg.inv(x.T @ x)
        self.a, self.a_se = float(beta[0]), math.sqrt(cov[0, 0])
        self.c = {j: float(beta[1 + i]) for i, j in enumerate(ratios)}
        self.c_se = {j: math.sqrt(cov[1 + i, 1 + i]) for i, j in enumerate(ratios)}

    def k_inf(self):
        return 1 / math.sqrt(self.a) if self.a > 0 else math.inf

    def k_inf_interval(self):
        half = student_t(self.dof) * self.a_se
        lo_a, hi_a = self.a - half, self.a + half
        return (1 / math.sqrt(hi_a) if hi_a > 0 else math.inf, 1 / math.sqrt(lo_a) if lo_a > 0 else math.inf)

    def k_inf_se(self):
        """Delta method: d(A^-1/2)/dA = -A^-3/2 / 2."""
        return 0.5 * self.a ** -1.5 * self.a_se if self.a > 0 else math.inf

    def w0(self, ratio):
        return self.c[ratio] / self.a if self.a > 0 else math.inf

    def size_independent_from(self, ratio):
        return self.w0(ratio) / (1 / WITHIN ** 2 - 1)

    def k_at(self, ratio, w):
        return 1 / math.sqrt(self.a + self.c[ratio] / w)


def fits(rows):
    """The joint fit and one per notch ratio (where that ratio has two sizes or more)."""
    out = {"joint": Fit(rows)}
    for j in sorted({r["aW"] for r in rows}):
        sub = [r for r in rows if r["aW"] == j]
        if len({r["W"] for r in sub}) >= 2 and len(sub) >= 3:
            out[f"a/W {j:g}"] = Fit(sub)
    return out


def write(rows, out):
    out.mkdir(parents=True, exist_ok=True)
    sizes = by_size(rows)
    fitted = fits(rows)
    with open(out / "size_effect.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["row", "notch_ratio_a_over_W", "beam_depth_W_mm", "beams", T.fracture_toughness_MPa_sqrt_m,
                    "fracture_toughness_se_MPa_sqrt_m", T.fracture_energy_J_per_m2, "k_inf_low_MPa_sqrt_m",
                    "k_inf_high_MPa_sqrt_m", "transitional_size_W0_mm", "size_independent_from_W_mm"])
        for (j, size), (n, k, se, g) in sizes.items():
            w.writerow(["size", j, size, n, f"{k:.6g}", f"{se:.3g}", f"{g:.4g}", "", "", "", ""])
        for name, fit in fitted.items():
            lo, hi = fit.k_inf_interval()
            for j in fit.ratios:
                w.writerow([f"fit {name}", j, "inf", fit.n, f"{fit.k_inf():.6g}", f"{fit.k_inf_se():.3g}", "",
                            f"{lo:.4g}", f"{hi:.4g}", f"{fit.w0(j):.4g}", f"{fit.size_independent_from(j):.4g}"])
    lines = ["| a/W | W (mm) | beams | K (MPa sqrt(m)) | G_c books (J/m^2) |", "|---|---|---|---|---|"]
    for (j, size), (n, k, se, g) in sizes.items():
        lines.append(f"| {j:g} | {size:g} | {n} | {k:.3f} +- {se:.3f} | {g:.2f} |")
    lines += ["", "| fit | K_inf (MPa sqrt(m)) | 95 % interval | W_0 (mm) | within 10 % of K_inf from W (mm) |",
              "|---|---|---|---|---|"]
    for name, fit in fitted.items():
        lo, hi = fit.k_inf_interval()
        for j in fit.ratios:
            lines.append(f"| {name} (a/W {j:g}) | {fit.k_inf():.3f} +- {fit.k_inf_se():.3f} | {lo:.3f} - {hi:.3f} | "
                         f"{fit.w0(j):.3f} | {fit.size_independent_from(j):.2f} |")
    (out / "size_effect.md").write_text("\n".join(lines) + "\n")
    plot(rows, fitted["joint"], out / "size_effect.png")
    return "\n".join(lines)


def plot(rows, fit, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    sizes = by_size(rows)
    w_max = max(r["W"] for r in rows)
    for i, j in enumerate(fit.ratios):
        sub = [r for r in rows if r["aW"] == j]
        shift = 1.04 ** (i - (len(fit.ratios) - 1) / 2)  # side by side on the log axis
        dots, = ax.plot([r["W"] * shift for r in sub], [r["K"] for r in sub], "o", ms=3, alpha=0.35)
        colour = dots.get_color()
        means = [(size, k, student_t(n - 1) * se if n > 1 else 0.0) for (jj, size), (n, k, se, _) in sizes.items()
                 if jj == j]
        ax.errorbar([m[0] * shift for m in means], [m[1] for m in means], yerr=[m[2] for m in means], fmt="s",
                    color=colour, capsize=3, label=f"a/W = {j:g}: mean, 95 % interval (dots: packings)")
        w_in = np.geomspace(0.3, w_max, 100)
        w_out = np.geomspace(w_max, 40, 100)
        ax.plot(w_in, [fit.k_at(j, x) for x in w_in], "-", color=colour,
                label=f"size-effect law, a/W = {j:g} (W0 = {fit.w0(j):.2f} mm)")
        ax.plot(w_out, [fit.k_at(j, x) for x in w_out], ":", color=colour)
    lo, hi = fit.k_inf_interval()
    ax.axhline(fit.k_inf(), color="grey", lw=1, label=f"K_inf {fit.k_inf():.2f} (95 % interval {lo:.2f}-{hi:.2f})")
    ax.axhline(0.77, color="k", ls="--", lw=1, label="soda-lime glass, 0.77 MPa sqrt(m)")
    ax.set_xscale("log")
    ax.set_xlabel("beam depth W (mm)")
    ax.set_ylabel("K_IC from the peak load (MPa sqrt(m))")
    ax.set_ylim(0, max(1.2, 1.1 * max(r["K"] for r in rows)))
    ax.legend(fontsize=7, loc="lower right")
    per_size = collections.Counter((r["aW"], r["W"]) for r in rows)
    counts = sorted(set(per_size.values()))
    packings = f"{counts[0]}" if len(counts) == 1 else f"{counts[0]}-{counts[-1]}"
    ax.set_title(f"Size effect of the DEM glass's toughness (SENB, {packings} packings per size; "
                 f"curves: the joint fit)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)


def main():
    root = pathlib.Path(__file__).resolve().parents[1]
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("record", nargs="?", default=root / "data/studies/results/toughness_size.csv", type=pathlib.Path)
    ap.add_argument("--out", default=pathlib.Path("toughness_size"), type=pathlib.Path)
    args = ap.parse_args()
    print(write(read_record(args.record), args.out))


if __name__ == "__main__":
    main()
