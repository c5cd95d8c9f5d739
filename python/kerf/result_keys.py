"""The keys of kerf-dem's results in summary.json and the columns of its CSV files, generated from their
result tables (kerf-dem results --python > python/kerf/result_keys.py; tests/cli/dem_results_cli.sh checks it
is current). Read a result or a column by its name here, never by a literal: a key renamed in its table then
fails where it is read, by name."""


class CutResults:
    """results: cut: one run's (with `--replicates`, the means over the replicates)."""

    main_force_N = "main_force_N"
    thrust_force_N = "thrust_force_N"
    main_force_std_N = "main_force_std_N"
    thrust_force_std_N = "thrust_force_std_N"
    main_force_sem_N = "main_force_sem_N"
    thrust_force_sem_N = "thrust_force_sem_N"
    main_force_sem_method = "main_force_sem_method"
    thrust_force_sem_method = "thrust_force_sem_method"
    main_force_inefficiency_samples = "main_force_inefficiency_samples"
    thrust_force_inefficiency_samples = "thrust_force_inefficiency_samples"
    main_force_batch_samples = "main_force_batch_samples"
    thrust_force_batch_samples = "thrust_force_batch_samples"
    steady_from_travel_mm = "steady_from_travel_mm"
    steady_to_travel_mm = "steady_to_travel_mm"
    steady_samples = "steady_samples"
    contact_share_steady = "contact_share_steady"
    steady = "steady"
    not_steady_reason = "not_steady_reason"
    width_mm = "width_mm"
    cracks_tensile = "cracks_tensile"
    cracks_shear = "cracks_shear"
    cracks_chip = "cracks_chip"
    cracks_subsurface = "cracks_subsurface"
    subsurface_damage_depth_um = "subsurface_damage_depth_um"
    steady_machined_from_x_mm = "steady_machined_from_x_mm"
    steady_machined_to_x_mm = "steady_machined_to_x_mm"
    cracks_subsurface_steady = "cracks_subsurface_steady"
    subsurface_damage_depth_steady_um = "subsurface_damage_depth_steady_um"
    subsurface_damage_depth_steady_p95_um = "subsurface_damage_depth_steady_p95_um"
    surface_y_mm = "surface_y_mm"
    cut_line_y_mm = "cut_line_y_mm"
    particles_removed_by_grooves = "particles_removed_by_grooves"
    travel_windows = "travel_windows"
    grains_crushed = "grains_crushed"
    grains_crushed_mass_kg = "grains_crushed_mass_kg"
    tied_disks_crushed = "tied_disks_crushed"
    tied_disks_crushed_mass_kg = "tied_disks_crushed_mass_kg"
    energy_tool_work_steady_J = "energy_tool_work_steady_J"
    energy_dissipated_steady_J = "energy_dissipated_steady_J"
    energy_left_kinetic_steady_J = "energy_left_kinetic_steady_J"
    energy_left_strain_steady_J = "energy_left_strain_steady_J"
    energy_stored_change_steady_J = "energy_stored_change_steady_J"
    edge_observations_steady = "edge_observations_steady"
    edge_touches_tied_share_steady = "edge_touches_tied_share_steady"
    edge_touches_loose_share_steady = "edge_touches_loose_share_steady"
    edge_touches_nothing_share_steady = "edge_touches_nothing_share_steady"
    tied_share_ahead_depth_0_25_um_steady = "tied_share_ahead_depth_0_25_um_steady"
    tied_share_ahead_depth_25_50_um_steady = "tied_share_ahead_depth_25_50_um_steady"
    tied_share_ahead_depth_50_100_um_steady = "tied_share_ahead_depth_50_100_um_steady"
    tied_share_behind_depth_0_25_um_steady = "tied_share_behind_depth_0_25_um_steady"
    tied_share_behind_depth_25_50_um_steady = "tied_share_behind_depth_25_50_um_steady"
    tied_share_behind_depth_50_100_um_steady = "tied_share_behind_depth_50_100_um_steady"
    edge_zone_samples_steady = "edge_zone_samples_steady"
    edge_zone_intact_share_steady = "edge_zone_intact_share_steady"
    edge_zone_cutting_force_N_per_mm = "edge_zone_cutting_force_N_per_mm"
    edge_zone_thrust_force_N_per_mm = "edge_zone_thrust_force_N_per_mm"
    edge_zone_removed_tied_disks = "edge_zone_removed_tied_disks"
    edge_zone_removed_loose_disks = "edge_zone_removed_loose_disks"
    edge_zone_removed_mass_kg = "edge_zone_removed_mass_kg"
    energy_edge_zone_tool_work_steady_J = "energy_edge_zone_tool_work_steady_J"
    energy_edge_zone_reaction_work_steady_J = "energy_edge_zone_reaction_work_steady_J"
    energy_edge_layer_steady_J = "energy_edge_layer_steady_J"
    main_force_replicate_std_N = "main_force_replicate_std_N"
    thrust_force_replicate_std_N = "thrust_force_replicate_std_N"
    cracks_tensile_replicate_std = "cracks_tensile_replicate_std"
    cracks_shear_replicate_std = "cracks_shear_replicate_std"
    subsurface_damage_depth_replicate_std_um = "subsurface_damage_depth_replicate_std_um"
    cracks_subsurface_steady_replicate_std = "cracks_subsurface_steady_replicate_std"
    subsurface_damage_depth_steady_replicate_std_um = "subsurface_damage_depth_steady_replicate_std_um"
    subsurface_damage_depth_steady_p95_replicate_std_um = "subsurface_damage_depth_steady_p95_replicate_std_um"
    main_force_sem_within_cuts_N = "main_force_sem_within_cuts_N"
    thrust_force_sem_within_cuts_N = "thrust_force_sem_within_cuts_N"
    cutting_force_N_per_mm = "cutting_force_N_per_mm"
    thrust_force_N_per_mm = "thrust_force_N_per_mm"
    cutting_force_N = "cutting_force_N"
    cutting_force_std_N = "cutting_force_std_N"
    cutting_force_sem_N = "cutting_force_sem_N"
    cutting_force_sem_method = "cutting_force_sem_method"
    cutting_force_inefficiency_samples = "cutting_force_inefficiency_samples"
    cutting_force_batch_samples = "cutting_force_batch_samples"
    cutting_force_replicate_std_N = "cutting_force_replicate_std_N"
    cutting_force_sem_within_cuts_N = "cutting_force_sem_within_cuts_N"


class TravelWindowResults:
    """results.travel_windows: cut: each stretch of `cut.window_mm` of travel (its forces also under their current names)."""

    from_travel_mm = "from_travel_mm"
    to_travel_mm = "to_travel_mm"
    main_force_N = "main_force_N"
    thrust_force_N = "thrust_force_N"
    samples = "samples"


class ActiveWindowResults:
    """active_window: cut, with an active window."""

    rebuilds = "rebuilds"
    largest_window_particles = "largest_window_particles"
    mean_window_particles = "mean_window_particles"
    chip_particles_removed = "chip_particles_removed"
    chip_mass_removed_kg = "chip_mass_removed_kg"
    chip_cracks_removed = "chip_cracks_removed"
    damage_depth_limit_um = "damage_depth_limit_um"


class LabTestResults:
    """results: tension, compression."""

    youngs_modulus_GPa = "youngs_modulus_GPa"
    poissons_ratio = "poissons_ratio"
    tensile_strength_MPa = "tensile_strength_MPa"
    compressive_strength_MPa = "compressive_strength_MPa"
    strain_at_peak = "strain_at_peak"
    n_tension_cracks = "n_tension_cracks"
    n_shear_cracks = "n_shear_cracks"
    stop_reason = "stop_reason"
    speed_m_per_s = "speed_m_per_s"
    specimen_width_mm = "specimen_width_mm"
    gauge_length_mm = "gauge_length_mm"


class LabTestCheckResults:
    """results.quasi_static_check: tension, compression, with `loading.quasi_static_check`: the test again at half the speed."""

    speed_m_per_s = "speed_m_per_s"
    peak_stress_MPa = "peak_stress_MPa"
    peak_change_percent = "peak_change_percent"
    youngs_modulus_change_percent = "youngs_modulus_change_percent"
    wall_time_s = "wall_time_s"
    tolerance_percent = "tolerance_percent"
    verdict = "verdict"


class ToughnessResults:
    """results: toughness: the means over the packings (`--replicates N`)."""

    fracture_toughness_MPa_sqrt_m = "fracture_toughness_MPa_sqrt_m"
    fracture_energy_J_per_m2 = "fracture_energy_J_per_m2"
    work_of_fracture_J_per_m2 = "work_of_fracture_J_per_m2"
    irwin_energy_J_per_m2 = "irwin_energy_J_per_m2"
    fracture_energy_over_irwin_energy = "fracture_energy_over_irwin_energy"
    youngs_modulus_for_irwin_GPa = "youngs_modulus_for_irwin_GPa"
    packings = "packings"
    depth_W_mm = "depth_W_mm"
    span_S_mm = "span_S_mm"
    length_mm = "length_mm"
    thickness_B_mm = "thickness_B_mm"
    notch_depth_a_mm = "notch_depth_a_mm"
    notch_over_depth = "notch_over_depth"
    geometry_factor = "geometry_factor"
    speed_m_per_s = "speed_m_per_s"
    peak_window_um = "peak_window_um"
    per_packing = "per_packing"
    fracture_toughness_sem_MPa_sqrt_m = "fracture_toughness_sem_MPa_sqrt_m"
    fracture_energy_sem_J_per_m2 = "fracture_energy_sem_J_per_m2"
    work_of_fracture_sem_J_per_m2 = "work_of_fracture_sem_J_per_m2"
    irwin_energy_sem_J_per_m2 = "irwin_energy_sem_J_per_m2"


class ToughnessPackingResults:
    """results.per_packing: toughness: each packing's."""

    fracture_toughness_MPa_sqrt_m = "fracture_toughness_MPa_sqrt_m"
    fracture_energy_J_per_m2 = "fracture_energy_J_per_m2"
    work_of_fracture_J_per_m2 = "work_of_fracture_J_per_m2"
    irwin_energy_J_per_m2 = "irwin_energy_J_per_m2"
    peak_load_N = "peak_load_N"
    raw_peak_load_N = "raw_peak_load_N"
    raw_peak_toughness_MPa_sqrt_m = "raw_peak_toughness_MPa_sqrt_m"
    deflection_at_peak_um = "deflection_at_peak_um"
    external_work_J = "external_work_J"
    broken_through = "broken_through"
    deflection_broken_through_um = "deflection_broken_through_um"
    n_cracks = "n_cracks"
    n_notch_disks_removed = "n_notch_disks_removed"
    n_notch_joints_retired = "n_notch_joints_retired"
    stop_reason = "stop_reason"
    steps = "steps"
    wall_time_s = "wall_time_s"


class ToughnessCheckResults:
    """results.quasi_static_check: toughness, with `toughness.quasi_static_check`: the first packing again at half the speed."""

    speed_m_per_s = "speed_m_per_s"
    peak_load_N = "peak_load_N"
    peak_change_percent = "peak_change_percent"
    fracture_toughness_MPa_sqrt_m = "fracture_toughness_MPa_sqrt_m"
    fracture_energy_J_per_m2 = "fracture_energy_J_per_m2"
    fracture_energy_change_percent = "fracture_energy_change_percent"
    tolerance_percent = "tolerance_percent"
    verdict = "verdict"
    wall_time_s = "wall_time_s"


class CalibrateResults:
    """results: calibrate."""

    converged = "converged"
    max_error_percent = "max_error_percent"
    evaluations = "evaluations"
    targets = "targets"
    achieved = "achieved"
    calibrated_material = "calibrated_material"
    toughness_error_percent = "toughness_error_percent"


class CalibrateCutResults:
    """results: calibrate_cut (each `main_force_*` also under its current name, `cutting_force_*`)."""

    converged = "converged"
    target_cutting_force_N = "target_cutting_force_N"
    target_main_force_N = "target_main_force_N"
    target_source = "target_source"
    strength_factor = "strength_factor"
    main_force_N = "main_force_N"
    main_force_standard_error_N = "main_force_standard_error_N"
    relative_error_percent = "relative_error_percent"
    evaluations = "evaluations"
    calibrated_material = "calibrated_material"


class CalibrateCutEvaluationResults:
    """results.evaluations: calibrate_cut: each evaluation's row (each `main_force_*` also as `cutting_force_*`)."""

    evaluation = "evaluation"
    strength_factor = "strength_factor"
    tensile_strength_MPa = "tensile_strength_MPa"
    cohesion_MPa = "cohesion_MPa"
    main_force_N = "main_force_N"
    main_force_replicate_std_N = "main_force_replicate_std_N"
    thrust_force_N = "thrust_force_N"
    thrust_force_replicate_std_N = "thrust_force_replicate_std_N"
    relative_error_percent = "relative_error_percent"
    directory = "directory"


class ForcesCsvColumns:
    """forces.csv: cut: one row per sample, as the cut goes (the columns in this order)."""

    tool_travel_mm = "tool_travel_mm"
    time_s = "time_s"
    cutting_force_N = "cutting_force_N"
    thrust_force_N = "thrust_force_N"
    cutting_force_N_per_mm = "cutting_force_N_per_mm"
    thrust_force_N_per_mm = "thrust_force_N_per_mm"
    main_force_N = "main_force_N"


class CracksColumns:
    """cracks.csv: cut, tension, compression, toughness: one row per broken element (the columns in this order)."""

    time_s = "time_s"
    x_mm = "x_mm"
    y_mm = "y_mm"
    orientation_deg = "orientation_deg"
    length_um = "length_um"
    mode = "mode"
    bond = "bond"
    element = "element"
    place = "place"


class CurveColumns:
    """curve.csv: tension, compression: one row per sample (the columns in this order)."""

    time_s = "time_s"
    axial_strain = "axial_strain"
    lateral_strain = "lateral_strain"
    stress_MPa = "stress_MPa"
    tension_cracks = "tension_cracks"
    shear_cracks = "shear_cracks"


class ToughnessCurveColumns:
    """curve.csv: toughness: one row per sample, each packing's curve after the other (the columns in this order)."""

    seed = "seed"
    time_s = "time_s"
    deflection_um = "deflection_um"
    load_N = "load_N"
    smoothed_load_N = "smoothed_load_N"
    support_load_N = "support_load_N"
    external_work_J = "external_work_J"
    stored_elastic_energy_J = "stored_elastic_energy_J"
    kinetic_energy_J = "kinetic_energy_J"
    n_cracks = "n_cracks"


class CalibrationLogColumns:
    """calibration_log.csv: calibrate: one row per evaluation (the columns in this order)."""

    evaluation = "evaluation"
    effective_modulus_GPa = "effective_modulus_GPa"
    stiffness_ratio = "stiffness_ratio"
    tensile_strength_MPa = "tensile_strength_MPa"
    cohesion_MPa = "cohesion_MPa"
    youngs_modulus_GPa = "youngs_modulus_GPa"
    poissons_ratio = "poissons_ratio"
    macro_tensile_strength_MPa = "macro_tensile_strength_MPa"
    macro_compressive_strength_MPa = "macro_compressive_strength_MPa"
    max_error_percent = "max_error_percent"
    wall_time_s = "wall_time_s"
    fracture_energy_J_per_m2 = "fracture_energy_J_per_m2"
    macro_fracture_toughness_MPa_sqrt_m = "macro_fracture_toughness_MPa_sqrt_m"
    toughness_error_percent = "toughness_error_percent"


class CalibrateCutLogColumns:
    """calibration_log.csv: calibrate_cut: one row per evaluation (the columns in this order)."""

    evaluation = "evaluation"
    strength_factor = "strength_factor"
    tensile_strength_MPa = "tensile_strength_MPa"
    cohesion_MPa = "cohesion_MPa"
    main_force_N = "main_force_N"
    main_force_replicate_std_N = "main_force_replicate_std_N"
    thrust_force_N = "thrust_force_N"
    thrust_force_replicate_std_N = "thrust_force_replicate_std_N"
    relative_error_percent = "relative_error_percent"
    wall_time_s = "wall_time_s"


def keys(table):
    """The keys of a table above, in its order."""
    return [value for name, value in vars(table).items() if not name.startswith("_")]
