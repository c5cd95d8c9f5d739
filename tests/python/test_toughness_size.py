"""analysis/toughness_size.py: Bazant's size-effect fit on synthetic records with known answers."""
import csv
import math
import random

import pytest

from kerf.result_keys import ToughnessResults as T
from repo_scripts import load

ts = load("analysis/toughness_size.py")


def beams(k_inf, w0, sizes=(0.5, 1.0, 2.0), ratios=(0.3, 0.5), seeds=(1, 2, 3), noise=0.0, rng=None):
    """K(W) = K_inf / sqrt(1 + W0_j / W), W0 per notch ratio, optionally with relative noise."""
    rows = []
    for j in ratios:
        for w in sizes:
            for s in seeds:
                k = k_inf / math.sqrt(1 + w0[j] / w)
                if noise:
                    k *= 1 + rng.gauss(0, noise)
                rows.append({"W": w, "aW": j, "seed": s, "K": k, "G": k * k * 1e12 / 71e9})
    return rows


def test_a_noise_free_record_gives_back_k_inf_and_w0():
    fit = ts.Fit(beams(0.77, {0.3: 0.4, 0.5: 0.9}, noise=0))
    assert math.isclose(fit.k_inf(), 0.77, rel_tol=1e-9)
    assert math.isclose(fit.w0(0.3), 0.4, rel_tol=1e-9)
    assert math.isclose(fit.w0(0.5), 0.9, rel_tol=1e-9)
    # K(W) / K_inf = 0.9 exactly at the reported size.
    w = fit.size_independent_from(0.3)
    assert math.isclose(fit.k_at(0.3, w) / fit.k_inf(), 0.9, rel_tol=1e-9)


def test_the_interval_covers_k_inf_about_95_percent_of_the_time():
    rng = random.Random(37)
    hits, trials = 0, 400
    for _ in range(trials):
        lo, hi = ts.Fit(beams(0.77, {0.3: 0.4, 0.5: 0.9}, noise=0.08, rng=rng)).k_inf_interval()
        hits += lo <= 0.77 <= hi
    assert 0.90 <= hits / trials <= 0.99


def test_a_size_independent_toughness_has_w0_near_zero():
    rng = random.Random(3)
    fit = ts.Fit(beams(0.6, {0.3: 0.0, 0.5: 0.0}, noise=0.01, rng=rng))
    assert abs(fit.w0(0.3)) < 0.05 and abs(fit.w0(0.5)) < 0.05
    assert math.isclose(fit.k_inf(), 0.6, rel_tol=0.02)


def test_one_size_cannot_be_fitted():
    with pytest.raises(ValueError):
        ts.Fit(beams(0.77, {0.3: 0.4}, sizes=(1.0,), ratios=(0.3,)))


def test_the_record_round_trip_and_outputs(tmp_path):
    rows = beams(0.77, {0.3: 0.4, 0.5: 0.9}, noise=0)
    record = tmp_path / "record.csv"
    with open(record, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["condition", "beam_depth_W_mm", "notch_ratio_a_over_W", "seed", T.fracture_toughness_MPa_sqrt_m,
                    T.fracture_energy_J_per_m2])
        for r in rows:
            w.writerow([1, r["W"], r["aW"], r["seed"], repr(r["K"]), repr(r["G"])])
    text = ts.write(ts.read_record(record), tmp_path / "out")
    assert "| joint (a/W 0.3) | 0.770" in text
    assert (tmp_path / "out" / "size_effect.png").stat().st_size > 0
    with open(tmp_path / "out" / "size_effect.csv") as f:
        fit_rows = [r for r in csv.DictReader(f) if r["row"] == "fit joint"]
    assert len(fit_rows) == 2
    assert math.isclose(float(fit_rows[0][T.fracture_toughness_MPa_sqrt_m]), 0.77, rel_tol=1e-5)
