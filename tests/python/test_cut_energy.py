"""analysis/cut_energy.py: the broken joints' energy against the tool's work, on a synthetic cut with a known answer."""
import json
import math

from repo_scripts import load

from kerf.result_keys import CracksColumns as C
from kerf.result_keys import CutResults as R
from kerf.result_keys import keys

ce = load("analysis/cut_energy.py")

MATERIAL = {"name": "glass", "bond_effective_modulus_GPa": 100.0, "bond_stiffness_ratio": 2.0,
            "tensile_strength_MPa": 100.0, "cohesion_MPa": 200.0}


def write_cut(folder, main_force_n=0.5, grooves="none", seed=1, material=MATERIAL):
    """A cut whose steady part covers 1 mm of travel and x in [2, 3] mm; cracks inside and outside it."""
    folder.mkdir(parents=True)
    summary = {"material": material,
               "specimen": {"thickness_mm": 1.0, "radius_min_um": 10.0, "radius_max_um": 10.0, "radius_scale": 1.0,
                            "seed": seed},
               "cut": {"cut": {"depth_of_cut_mm": 0.1}, "grooves": {"shape": grooves},
                       "active_window": {"enabled": True, "ahead_depths": 7, "behind_depths": 3, "below_depths": 4}},
               "results": {R.main_force_N: main_force_n, R.steady_from_travel_mm: 0.5, R.steady_to_travel_mm: 1.5,
                           R.steady_machined_from_x_mm: 3.0, R.steady_machined_to_x_mm: 2.0}}
    (folder / "summary.json").write_text(json.dumps(summary))
    rows = [",".join(keys(C))]  # the rows below in its order
    rows += [f"0,{2.0 + 0.1 * k},0.5,0,10,tension,{k},0,subsurface" for k in range(10)]  # inside
    rows += ["0,2.5,0.95,0,10,shear,20,0,chip", "0,1.0,0.5,0,10,tension,21,0,subsurface",  # the second outside
             "0,3.5,0.95,0,10,tension,22,0,chip"]  # outside
    (folder / "cracks.csv").write_text("\n".join(rows) + "\n")


def add_books(folder):
    """The cut's energy books: work 0.6 mJ, 0.5 dissipated, 0.09 carried off as kinetic and 0.01 as strain energy."""
    summary = json.loads((folder / "summary.json").read_text())
    summary["results"].update({R.energy_tool_work_steady_J: 0.6e-3, R.energy_dissipated_steady_J: 0.5e-3,
                               R.energy_left_kinetic_steady_J: 0.09e-3, R.energy_left_strain_steady_J: 0.01e-3})
    (folder / "summary.json").write_text(json.dumps(summary))


def test_the_energy_of_each_broken_element_and_its_share_of_the_work(tmp_path):
    write_cut(tmp_path / "a")
    key, seed, work, energy = ce.cut_energy(tmp_path / "a")
    assert key == ("glass, radii 10-10 um", "0.7/0.3/0.4 mm", "regular", 0.1) and seed == 1
    assert math.isclose(work, 0.5e-3)  # 0.5 N over 1 mm
    area, joint = 10e-6 * 1e-3, 20e-6
    tension = 0.5 * (100e6) ** 2 * area * joint / 100e9  # sigma_t^2 A L / (2 Ebar*)
    shear = 0.5 * (200e6) ** 2 * area * joint * 2.0 / 100e9  # c^2 A L kappa / (2 Ebar*)
    assert math.isclose(energy["subsurface"], 10 * tension)
    assert math.isclose(energy["chip"], shear)


def test_a_softening_joint_adds_its_fracture_energy_per_element_area(tmp_path):
    write_cut(tmp_path / "a", material={**MATERIAL, "fracture_energy_J_per_m2": 5.0})
    write_cut(tmp_path / "b")
    _, _, _, soft = ce.cut_energy(tmp_path / "a")
    _, _, _, plain = ce.cut_energy(tmp_path / "b")
    assert math.isclose(soft["subsurface"] - plain["subsurface"], 10 * 5.0 * 10e-6 * 1e-3)


def test_shares_are_means_over_packings_with_intervals(tmp_path):
    for seed, force in ((1, 0.5), (2, 0.25)):
        write_cut(tmp_path / "study" / "items" / f"condition_1_seed_{seed}", main_force_n=force, seed=seed)
    cuts = [ce.cut_energy(f) for f in ce.folders([tmp_path / "study"])]
    shares, = ce.table(cuts).values()
    total, chip, sub = shares["joints"], shares["chip"], shares["subsurface"]
    one = (cuts[0][3]["chip"] + cuts[0][3]["subsurface"]) / 0.5e-3
    assert total.n == 2 and math.isclose(total.value, 1.5 * one)  # shares one and two: mean 1.5
    assert total.low < total.value < total.high
    assert math.isclose(chip.value + sub.value, total.value)
    assert "friction" not in shares  # no books


def test_the_books_give_friction_as_the_dissipated_rest_and_their_own_work(tmp_path):
    write_cut(tmp_path / "a")
    add_books(tmp_path / "a")
    _, _, work, energy = ce.cut_energy(tmp_path / "a")
    assert work == 0.6e-3
    assert math.isclose(energy["friction"], 0.5e-3 - energy["chip"] - energy["subsurface"])
    shares, = ce.table([ce.cut_energy(tmp_path / "a")]).values()
    assert math.isclose(shares["carried_kinetic"].value, 0.15)
    assert math.isclose(shares["joints"].value + shares["friction"].value, 0.5 / 0.6)


def test_the_figure_draws_the_conditions_with_books(tmp_path):
    write_cut(tmp_path / "a")
    add_books(tmp_path / "a")
    assert ce.main([str(tmp_path / "a"), "--figure", str(tmp_path / "f.png")]) == 0
    assert (tmp_path / "f.png").read_bytes()[:4] == b"\x89PNG"


def test_a_condition_names_the_options_that_change_the_cut():
    summary = {"material": {"name": "glass"}, "specimen": {"radius_min_um": 5.0, "radius_max_um": 6.5},
               "cut": {"cut": {"depth_of_cut_mm": 0.1}, "tool": {"friction_coefficient": 0.0, "edge_radius_um": 20.0},
                       "grooves": {"shape": "rectangular", "damage_depth_um": 25.0, "damage_broken_fraction": 0.5},
                       "active_window": {"enabled": True, "ahead_depths": 7, "behind_depths": 3, "below_depths": 4,
                                         "grain_strength_MPa": 85.0, "tied_grain_strength_MPa": 330.0,
                                         "absorbing_depths": 1.0,
                                         "remove_loose_fragments": True}}}
    glass, window, surface, depth = ce.condition_of(summary)
    for part in ("radii 5-6.5 um", "tool mu 0", "edge radius 20 um", "grains crush at 85 MPa",
                 "tied disks crush at 330 MPa", "loose fragments removed", "absorbing layer 1 depths"):
        assert part in glass
    assert (window, surface, depth) == ("0.7/0.3/0.4 mm", "rectangular (25 um layer, 0.5 broken)", 0.1)
    plain = {"material": {"name": "glass"}, "cut": {"cut": {"depth_of_cut_mm": 0.2}, "grooves": {"shape": "none"}}}
    assert ce.condition_of(plain) == ("glass", "whole", "regular", 0.2)
