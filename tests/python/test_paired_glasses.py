"""analysis/paired_glasses.py: cuts of two glasses paired by packing, on synthetic records with known answers."""
import math

from repo_scripts import load

from kerf.result_keys import CutResults as R

pg = load("analysis/paired_glasses.py")


def record(main, thrust, factor=1.0, groove_factor=1.0):
    """{(domain, surface, depth): {seed: row}}: regular forces main[s], grooved 0.6 main[s] x groove_factor."""
    out = {}
    for surface, f in (("regular", 1.0), ("rectangular", 0.6 * groove_factor)):
        out[("default", surface, 0.1)] = {
            s: {R.main_force_N: m * f * factor, R.thrust_force_N: t * f * factor, R.width_mm: 1.0,
                R.cracks_subsurface_steady: 1000.0 * s, R.contact_share_steady: 0.05,
                R.subsurface_damage_depth_steady_um: 300.0}
            for s, (m, t) in enumerate(zip(main, thrust), start=1)}
    return out


def test_a_glass_that_scales_every_force_has_that_paired_ratio_and_the_same_groove_effect():
    base = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5])
    other = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5], factor=1.25)
    text = pg.compare(base, other, "default", 0.1)
    assert "other / base 1.250 [1.250, 1.250]" in text
    assert "change +0.000" in text


def test_a_glass_that_halves_the_grooved_force_halves_the_groove_effect():
    base = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5])
    other = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5], groove_factor=0.5)
    _, b, o = pg.paired(base, other, ("default", "rectangular", 0.1), R.main_force_N)
    assert all(math.isclose(y, 0.5 * x) for x, y in zip(b, o))
    assert "base 0.600" in pg.compare(base, other, "default", 0.1).splitlines()[-2]
    assert "other 0.300" in pg.compare(base, other, "default", 0.1).splitlines()[-2]


def test_only_the_packings_both_records_have_are_paired():
    base = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5])
    other = record([0.5, 0.4], [0.4, 0.3])
    seeds, b, o = pg.paired(base, other, ("default", "regular", 0.1), R.main_force_N)
    assert seeds == [1, 2] and b == o


def test_a_quantity_one_record_does_not_keep_pairs_no_packing():
    base = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5])
    other = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5])
    for rows in other.values():
        for row in rows.values():
            del row[R.subsurface_damage_depth_steady_um]
    assert pg.paired(base, other, ("default", "regular", 0.1), R.subsurface_damage_depth_steady_um)[0] == []
    assert "deepest subsurface crack (um):\nshare in contact:" in pg.compare(base, other, "default", 0.1)


def test_the_window_or_the_depth_is_paired_packing_by_packing_within_one_record():
    one = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5])
    large = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5], factor=1.2, groove_factor=0.5)
    deep = record([0.5, 0.4, 0.45], [0.4, 0.3, 0.5], factor=1.5)
    one[("large", "regular", 0.1)] = large[("default", "regular", 0.1)]
    one[("large", "rectangular", 0.1)] = large[("default", "rectangular", 0.1)]
    one[("default", "regular", 0.2)] = deep[("default", "regular", 0.1)]
    text = pg.compare(one, one, "large", 0.1, base_domain="default")
    assert text.splitlines()[0] == "other: large window, 0.1 mm; base: default window, 0.1 mm"
    assert "regular      seeds [1, 2, 3]: base 0.45, other 0.54, other / base 1.200 [1.200, 1.200]" in text
    assert "rectangular  seeds [1, 2, 3]: base 0.27, other 0.162, other / base 0.600 [0.600, 0.600]" in text
    assert "base 0.600" in text.splitlines()[-2] and "other 0.300" in text.splitlines()[-2]
    deeper = pg.compare(one, one, "default", 0.2, base_depth=0.1)
    assert "other / base 1.500 [1.500, 1.500]" in deeper and "rectangular" not in deeper.split("thrust")[0]
    assert "nan" not in deeper and "groove effect main: fewer than two paired packings of each surface" in deeper
    assert pg.compare(one, one, "default", 0.1) == pg.compare(one, one, "default", 0.1, "default", 0.1)
