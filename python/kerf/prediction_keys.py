"""The columns of kerf-forces' predictions (their CSV row, kerf.predict's dict), generated from their result tables
(kerf-forces results --python > python/kerf/prediction_keys.py; tests/cli/forces_results_cli.sh checks it is
current): the orthogonal prediction's shared columns, its models' own (a class per unit), the trepanning
prediction's."""


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


class EdgeColumns:
    """The chip term's edge columns, in the row's order (models.force `auto`, `liu_li` and `transition`)."""

    friction_closure = "friction_closure"
    lower_limit_rule = "lower_limit_rule"
    lower_limit_deg = "lower_limit_deg"
    upper_limit_deg = "upper_limit_deg"
    stagnation_angle_deg = "stagnation_angle_deg"
    pole_deg = "pole_deg"
    ploughed_thickness_um = "ploughed_thickness_um"
    edge_cutting_force_N = "edge_cutting_force_N"
    edge_thrust_force_N = "edge_thrust_force_N"
    ploughing_model = "ploughing_model"
    friction_factor = "friction_factor"
    ploughing_attack_angle_deg = "ploughing_attack_angle_deg"


class OxleyColumns:
    """The Oxley solve's columns, in the row's order (models.force `auto` and `oxley`, or models.deformation = oxley)."""

    strain_rate_constant_C0 = "strain_rate_constant_C0"
    secondary_zone_ratio_delta = "secondary_zone_ratio_delta"
    interface_temperature_K = "interface_temperature_K"
    contact_length_oxley_mm = "contact_length_oxley_mm"
    oxley_residual = "oxley_residual"
    oxley_shear_angle_roots = "oxley_shear_angle_roots"


class TransitionColumns:
    """models.force = transition's own columns, in the row's order."""

    fracture_model = "fracture_model"
    ductile_layer_um = "ductile_layer_um"
    layer_cutting_force_N = "layer_cutting_force_N"
    layer_thrust_force_N = "layer_thrust_force_N"
    fracture_cutting_force_N = "fracture_cutting_force_N"
    fracture_thrust_force_N = "fracture_thrust_force_N"


class TrepanningColumns:
    """The columns of a trepanning prediction, in the row's order (the grit columns with models.trepanning.grits)."""

    force_model = "force_model"
    outer_diameter_mm = "outer_diameter_mm"
    inner_diameter_mm = "inner_diameter_mm"
    feed_rate_um_per_s = "feed_rate_um_per_s"
    spindle_speed_rpm = "spindle_speed_rpm"
    feed_per_rev_um = "feed_per_rev_um"
    axial_force_N = "axial_force_N"
    torque_N_m = "torque_N_m"
    axial_group_MPa = "axial_group_MPa"
    torque_group_MPa = "torque_group_MPa"
    grit_count = "grit_count"
    cutting_edges = "cutting_edges"
    feed_per_edge_um = "feed_per_edge_um"
    grit_depth_um = "grit_depth_um"
    grit_normal_force_N = "grit_normal_force_N"
    grit_tangential_force_N = "grit_tangential_force_N"
    critical_depth_nm = "critical_depth_nm"
    grit_regime = "grit_regime"


def keys(table):
    """The keys of a table above, in its order."""
    return [value for name, value in vars(table).items() if not name.startswith("_")]
