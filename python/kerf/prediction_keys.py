"""The columns of kerf-forces' orthogonal prediction (its CSV row, kerf.predict's dict), generated from their result
table (kerf-forces results --python > python/kerf/prediction_keys.py; tests/cli/forces_results_cli.sh checks it
is current). The models' own columns (edge, Oxley, the force model's) are not listed."""


class PredictionColumns:
    """The shared columns of an orthogonal prediction, in the row's order (the models' own between the flow state and the turning cut's)."""

    force_model = "force_model"
    material = "material"
    rake_deg = "rake_deg"
    edge_radius_um = "edge_radius_um"
    clearance_deg = "clearance_deg"
    speed_m_per_min = "speed_m_per_min"
    workpiece_temperature_K = "workpiece_temperature_K"
    scene_friction_angle_deg = "scene_friction_angle_deg"
    uncut_chip_thickness_um = "uncut_chip_thickness_um"
    width_mm = "width_mm"
    cutting_force_N = "cutting_force_N"
    thrust_force_N = "thrust_force_N"
    ploughing_cutting_force_N = "ploughing_cutting_force_N"
    ploughing_thrust_force_N = "ploughing_thrust_force_N"
    cutting_force_N_per_mm = "cutting_force_N_per_mm"
    thrust_force_N_per_mm = "thrust_force_N_per_mm"
    shear_angle_deg = "shear_angle_deg"
    friction_angle_deg = "friction_angle_deg"
    chip_ratio = "chip_ratio"
    chip_thickness_um = "chip_thickness_um"
    flow_stress_MPa = "flow_stress_MPa"
    shear_flow_stress_MPa = "shear_flow_stress_MPa"
    johnson_cook_stress_MPa = "johnson_cook_stress_MPa"
    hall_petch_stress_MPa = "hall_petch_stress_MPa"
    dislocation_stress_MPa = "dislocation_stress_MPa"
    hardness_flow_stress_MPa = "hardness_flow_stress_MPa"
    strain = "strain"
    strain_rate_per_s = "strain_rate_per_s"
    temperature_K = "temperature_K"
    feed_um_per_rev = "feed_um_per_rev"
    depth_of_cut_um = "depth_of_cut_um"
    maximum_chip_thickness_um = "maximum_chip_thickness_um"
    equivalent_chip_thickness_um = "equivalent_chip_thickness_um"
    engaged_edge_length_mm = "engaged_edge_length_mm"
    critical_depth_nm = "critical_depth_nm"
    regime = "regime"
    within_model_range = "within_model_range"
    guards = "guards"
    warnings = "warnings"


def keys(table):
    """The keys of a table above, in its order."""
    return [value for name, value in vars(table).items() if not name.startswith("_")]
