// What an orthogonal cut reports from its samples and cracks: the crack counts, the steady statistics, the travel
// windows' means, forces.csv; and the result tables of what it writes (kerf/dem/procedures/cut_results.hpp):
// summary.json's "results", its "travel_windows" and "active_window", forces.csv's columns, each key with its unit,
// meaning and value, written once.
#include "kerf/dem/procedures/cut_results.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/io.hpp"
#include "kerf/time_series.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

CutCrackCounts count_cut_cracks(const std::vector<CrackEvent>& cracks, double y_cut_m,
                                std::array<double, 2> steady_x_m) {
  CutCrackCounts n;
  std::vector<double> steady_depths_m;
  for (const auto& c : cracks) {
    (c.mode == BreakMode::tension ? n.tensile : n.shear)++;
    if (is_chip_crack(c.y_m, y_cut_m)) {
      ++n.chip;
      continue;
    }
    ++n.subsurface;
    n.subsurface_damage_depth_m = std::max(n.subsurface_damage_depth_m, y_cut_m - c.y_m);
    if (c.x_m >= steady_x_m[0] && c.x_m <= steady_x_m[1]) {
      ++n.subsurface_steady;
      n.subsurface_steady_damage_depth_m = std::max(n.subsurface_steady_damage_depth_m, y_cut_m - c.y_m);
      steady_depths_m.push_back(y_cut_m - c.y_m);
    }
  }
  if (!steady_depths_m.empty()) {  // nearest rank: the ceil(0.95 n)-th smallest depth
    const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(steady_depths_m.size())));
    const auto at = steady_depths_m.begin() + static_cast<std::ptrdiff_t>(rank - 1);
    std::nth_element(steady_depths_m.begin(), at, steady_depths_m.end());
    n.subsurface_steady_damage_depth_p95_m = *at;
  }
  return n;
}

void steady_statistics(CutResult& res, double from_travel_m) {
  double sm = 0, st = 0, sm2 = 0, st2 = 0;
  int n = 0, touching = 0;
  for (const auto& s : res.samples) {
    if (s.travel_m < from_travel_m) continue;
    sm += s.main_force_N, st += s.thrust_force_N;
    sm2 += s.main_force_N * s.main_force_N, st2 += s.thrust_force_N * s.thrust_force_N;
    touching += s.main_force_N > 0 ? 1 : 0;
    ++n;
  }
  res.n_steady_samples = n;
  res.steady_from_travel_m = from_travel_m;
  res.steady_to_travel_m = res.samples.empty() ? from_travel_m : res.samples.back().travel_m;
  if (n == 0) {
    res.main_force_N = res.thrust_force_N = res.main_force_std_N = res.thrust_force_std_N = 0;
    res.contact_share = 0;
    res.main_force_sem_N = res.thrust_force_sem_N = std::nan("");
    res.main_force_sem_method = res.thrust_force_sem_method = "none";
    res.steady = false;
    res.not_steady_reason =
        fmt::format("no sample at or beyond {:.4g} mm of travel, where the means start", units::m_to_mm(from_travel_m));
    return;
  }
  res.contact_share = static_cast<double>(touching) / n;
  res.main_force_N = sm / n;
  res.thrust_force_N = st / n;
  res.main_force_std_N = std::sqrt(std::max(0.0, sm2 / n - res.main_force_N * res.main_force_N));
  res.thrust_force_std_N = std::sqrt(std::max(0.0, st2 / n - res.thrust_force_N * res.thrust_force_N));
  std::vector<double> main, thrust;
  for (const auto& s : res.samples)
    if (s.travel_m >= from_travel_m) main.push_back(s.main_force_N), thrust.push_back(s.thrust_force_N);
  const BatchMeans bm = batch_means(main), bt = batch_means(thrust);
  res.main_force_sem_N = bm.best_standard_error(&res.main_force_sem_method);
  res.thrust_force_sem_N = bt.best_standard_error(&res.thrust_force_sem_method);
  res.main_force_inefficiency = bm.statistical_inefficiency,
  res.thrust_force_inefficiency = bt.statistical_inefficiency;
  res.main_force_batch_samples = bm.batch_length, res.thrust_force_batch_samples = bt.batch_length;
  // Steady: the means start after the entry (to 1e-4 of it: a scene's entry_fraction x length rounds) and each
  // has a standard error.
  std::vector<std::string> why;
  const double entry_mm = units::m_to_mm(kEntryTravelM);
  if (res.steady_to_travel_m <= kEntryTravelM)
    why.push_back(
        fmt::format("the cut travels {:.4g} mm, within the entry (the first {:g} mm; docs/dem.md, \"How "
                    "long a cut must be\"): cut further (cut.length_mm)",
                    units::m_to_mm(res.steady_to_travel_m), entry_mm));
  else if (from_travel_m < kEntryTravelM * (1 - 1e-4))
    why.push_back(
        fmt::format("the means start at {:.4g} mm of travel, within the entry (the first {:g} mm; "
                    "docs/dem.md, \"How long a cut must be\"): start them later (cut.entry_fraction)",
                    units::m_to_mm(from_travel_m), entry_mm));
  if (!std::isfinite(res.main_force_sem_N) || !std::isfinite(res.thrust_force_sem_N))
    why.push_back(fmt::format(
        "the standard error of the {} cannot be computed from {} samples (too few for batch "
        "means or the autocorrelation): cut further",
        !std::isfinite(res.main_force_sem_N) && !std::isfinite(res.thrust_force_sem_N) ? "main and thrust means"
        : !std::isfinite(res.main_force_sem_N)                                         ? "main mean"
                                                                                       : "thrust mean",
        n));
  res.steady = why.empty();
  res.not_steady_reason = fmt::format("{}", fmt::join(why, "; "));
}

std::vector<TravelWindow> travel_window_means(const std::vector<CutSample>& samples, double length_m, double window_m) {
  // Whole windows, not one more for the rounding of length / window (0.6 / 0.1 is 6.000000000000001).
  const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil(length_m / window_m * (1 - 1e-12))));
  std::vector<TravelWindow> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    out[k].from_m = static_cast<double>(k) * window_m;
    out[k].to_m = std::min(length_m, static_cast<double>(k + 1) * window_m);
  }
  for (const auto& s : samples) {
    const auto k = std::min(n - 1, static_cast<std::size_t>(std::max(0.0, s.travel_m / window_m)));
    out[k].main_force_N += s.main_force_N;
    out[k].thrust_force_N += s.thrust_force_N;
    ++out[k].n_samples;
  }
  for (auto& w : out)
    if (w.n_samples > 0) w.main_force_N /= w.n_samples, w.thrust_force_N /= w.n_samples;
  return out;
}

const ResultTable<CutForcesRow>& cut_forces_columns() {
  namespace c = forces_csv_keys;
  using Row = CutForcesRow;
  static const ResultTable<Row> table{
      result_number<Row>(c::tool_travel_mm, units::kMm, "the tool's travel", [](const Row& r) { return r.s.travel_m; }),
      result_value<Row>(c::time_s, "s", "time since the cut began", [](const Row& r) { return r.s.time_s; }),
      result_value<Row>(c::cutting_force_N, "N", "cutting force over the cut's width (summary.json's width_mm)",
                        [](const Row& r) { return r.s.main_force_N; }),
      result_value<Row>(c::thrust_force_N, "N", "thrust force over the cut's width",
                        [](const Row& r) { return r.s.thrust_force_N; }),
      result_value<Row>(c::cutting_force_N_per_mm, "N/mm", "cutting force per mm of width",
                        [](const Row& r) { return r.s.main_force_N / r.width_mm; }),
      result_value<Row>(c::thrust_force_N_per_mm, "N/mm", "thrust force per mm of width",
                        [](const Row& r) { return r.s.thrust_force_N / r.width_mm; }),
      result_value<Row>(c::main_force_N, "N", "cutting_force_N's old name (deprecated, removed in 0.3.0)",
                        [](const Row& r) { return r.s.main_force_N; })};
  return table;
}

std::string cut_forces_csv_header() {
  return results_csv_header(cut_forces_columns());
}

std::string cut_forces_csv_row(const CutSample& s, double width_m) {
  return results_csv_row(cut_forces_columns(), {s, units::m_to_mm(width_m)});
}

std::string cut_forces_csv(const CutResult& res) {
  std::string out = cut_forces_csv_header();
  for (const auto& s : res.samples) out += cut_forces_csv_row(s, res.width_m);
  return out;
}

// The result tables.

namespace {

namespace k = cut_keys;
using R = CutReport;

/// part / whole, null without a whole.
Json share(std::int64_t part, std::int64_t whole) {
  return whole > 0 ? Json(static_cast<double>(part) / static_cast<double>(whole)) : Json();
}

/// The forces' steady statistics, each for the main and the thrust force.
void add_force_results(ResultTable<R>& t) {
  t.push_back(result_value<R>(k::main_force_N, "N",
                              "mean cutting (main) force over the steady part, over the cut's width",
                              [](const R& c) { return c.res.main_force_N; }));
  t.push_back(result_value<R>(k::thrust_force_N, "N", "mean thrust force over the steady part",
                              [](const R& c) { return c.res.thrust_force_N; }));
  t.push_back(result_value<R>(k::main_force_std_N, "N",
                              "spread of the cutting force's samples (not an error of the mean: they are correlated)",
                              [](const R& c) { return c.res.main_force_std_N; }));
  t.push_back(result_value<R>(k::thrust_force_std_N, "N", "spread of the thrust force's samples",
                              [](const R& c) { return c.res.thrust_force_std_N; }));
  t.push_back(
      result_value<R>(k::main_force_sem_N, "N",
                      "standard error of the mean cutting force from its signal (null: the signal is too short)",
                      [](const R& c) { return finite_or_null(c.res.main_force_sem_N); }));
  t.push_back(result_value<R>(k::thrust_force_sem_N, "N", "standard error of the mean thrust force from its signal",
                              [](const R& c) { return finite_or_null(c.res.thrust_force_sem_N); }));
  t.push_back(result_value<R>(k::main_force_sem_method, "",
                              "how main_force_sem_N was found: `batch_means`, `autocorrelation` or `none`",
                              [](const R& c) { return c.res.main_force_sem_method; }));
  t.push_back(result_value<R>(k::thrust_force_sem_method, "", "how thrust_force_sem_N was found",
                              [](const R& c) { return c.res.thrust_force_sem_method; }));
  t.push_back(result_value<R>(k::main_force_inefficiency_samples, "",
                              "the cutting force signal's statistical inefficiency g, in samples",
                              [](const R& c) { return c.res.main_force_inefficiency; }));
  t.push_back(result_value<R>(k::thrust_force_inefficiency_samples, "",
                              "the thrust force signal's statistical inefficiency g, in samples",
                              [](const R& c) { return c.res.thrust_force_inefficiency; }));
  t.push_back(result_value<R>(k::main_force_batch_samples, "", "the cutting force's batch length, in samples",
                              [](const R& c) { return c.res.main_force_batch_samples; }));
  t.push_back(result_value<R>(k::thrust_force_batch_samples, "", "the thrust force's batch length, in samples",
                              [](const R& c) { return c.res.thrust_force_batch_samples; }));
}

/// The steady part, the cracks and the workpiece.
void add_cut_results(ResultTable<R>& t) {
  t.push_back(
      result_number<R>(k::steady_from_travel_mm, units::kMm,
                       "tool travel where the means start (the entry, cut.entry_fraction of the travel, left out)",
                       [](const R& c) { return c.res.steady_from_travel_m; }));
  t.push_back(result_number<R>(k::steady_to_travel_mm, units::kMm, "tool travel where the means end (the last sample)",
                               [](const R& c) { return c.res.steady_to_travel_m; }));
  t.push_back(result_value<R>(k::steady_samples, "", "samples in the means",
                              [](const R& c) { return c.res.n_steady_samples; }));
  t.push_back(result_value<R>(k::contact_share_steady, "",
                              "share of the steady samples with the tool in contact (cutting force > 0)",
                              [](const R& c) { return c.res.contact_share; }));
  t.push_back(result_value<R>(k::steady, "",
                              "whether the means are a steady cut's: they start after the entry and both have a "
                              "standard error",
                              [](const R& c) { return c.res.steady; }));
  t.push_back(result_value<R>(k::not_steady_reason, "",
                              "why the means are not steady, with what to change (null when they are)",
                              [](const R& c) { return c.res.steady ? Json() : Json(c.res.not_steady_reason); }));
  t.push_back(result_number<R>(k::width_mm, units::kMm,
                               "the cut's width (the specimen's thickness): the forces are over it",
                               [](const R& c) { return c.res.width_m; }));
  t.push_back(result_value<R>(k::cracks_tensile, "", "broken joint elements in tension",
                              [](const R& c) { return c.res.cracks.tensile; }));
  t.push_back(result_value<R>(k::cracks_shear, "", "broken joint elements in shear",
                              [](const R& c) { return c.res.cracks.shear; }));
  t.push_back(result_value<R>(k::cracks_chip, "", "cracks above the cut line (in the chip)",
                              [](const R& c) { return c.res.cracks.chip; }));
  t.push_back(result_value<R>(k::cracks_subsurface, "", "cracks below the cut line",
                              [](const R& c) { return c.res.cracks.subsurface; }));
  t.push_back(result_number<R>(k::subsurface_damage_depth_um, units::kUm,
                               "the deepest subsurface crack anywhere below the cut line",
                               [](const R& c) { return c.res.cracks.subsurface_damage_depth_m; }));
  t.push_back(result_number<R>(k::steady_machined_from_x_mm, units::kMm,
                               "x where the surface machined during the steady part starts",
                               [](const R& c) { return c.res.steady_machined_x_m[0]; }));
  t.push_back(result_number<R>(k::steady_machined_to_x_mm, units::kMm,
                               "x where the surface machined during the steady part ends",
                               [](const R& c) { return c.res.steady_machined_x_m[1]; }));
  t.push_back(result_value<R>(k::cracks_subsurface_steady, "",
                              "subsurface cracks under the surface machined during the steady part",
                              [](const R& c) { return c.res.cracks.subsurface_steady; }));
  t.push_back(result_number<R>(k::subsurface_damage_depth_steady_um, units::kUm,
                               "the deepest of those cracks below the cut line: the damage to report",
                               [](const R& c) { return c.res.cracks.subsurface_steady_damage_depth_m; }));
  t.push_back(result_number<R>(k::subsurface_damage_depth_steady_p95_um, units::kUm,
                               "the depth above which 95 % of those cracks lie (nearest rank)",
                               [](const R& c) { return c.res.cracks.subsurface_steady_damage_depth_p95_m; }));
  t.push_back(result_number<R>(k::surface_y_mm, units::kMm, "y of the uncut surface",
                               [](const R& c) { return c.res.y_top_m; }));
  t.push_back(result_number<R>(k::cut_line_y_mm, units::kMm, "y of the cut line (surface less the depth of cut)",
                               [](const R& c) { return c.res.y_cut_m; }));
  t.push_back(result_value<R>(k::particles_removed_by_grooves, "", "disks the grooves removed from the workpiece",
                              [](const R& c) { return c.res.n_removed_by_grooves; }));
  t.push_back(result_value<R>(k::travel_windows, "",
                              "the mean forces over each cut.window_mm of travel (a list; its keys below)",
                              [](const R& c) {
                                Json windows = Json::array();
                                for (const auto& w : c.res.travel_windows)
                                  windows.push_back(results_to_json(travel_window_results(), w));
                                return windows;
                              }));
}

/// What the options write: crushing grains, the energy books.
void add_option_results(ResultTable<R>& t) {
  const auto grains = [](const R& c) { return c.cut.window.grain_strength_Pa > 0; };
  const auto tied_grains = [](const R& c) { return c.cut.window.tied_grain_strength_Pa > 0; };
  const auto booked = [](const R& c) { return c.res.energy_booked; };
  t.push_back(result_if(
      result_value<R>(k::grains_crushed, "", "loose disks the tool crushed (with active_window.grain_strength_MPa)",
                      [](const R& c) { return c.res.window.chips.crushed_grains; }),
      grains));
  t.push_back(result_if(result_value<R>(k::grains_crushed_mass_kg, "kg", "their mass",
                                        [](const R& c) { return c.res.window.chips.crushed_mass_kg; }),
                        grains));
  t.push_back(result_if(result_value<R>(k::tied_disks_crushed, "",
                                        "the workpiece's own disks the tool crushed (with "
                                        "active_window.tied_grain_strength_MPa)",
                                        [](const R& c) { return c.res.window.chips.crushed_tied_disks; }),
                        tied_grains));
  t.push_back(result_if(result_value<R>(k::tied_disks_crushed_mass_kg, "kg", "their mass",
                                        [](const R& c) { return c.res.window.chips.crushed_tied_mass_kg; }),
                        tied_grains));
  const std::pair<std::string_view, double CutEnergy::*> energies[] = {
      {k::energy_tool_work_steady_J, &CutEnergy::tool_work_J},
      {k::energy_dissipated_steady_J, &CutEnergy::dissipated_J},
      {k::energy_left_kinetic_steady_J, &CutEnergy::left_kinetic_J},
      {k::energy_left_strain_steady_J, &CutEnergy::left_strain_J},
      {k::energy_stored_change_steady_J, &CutEnergy::stored_change_J}};
  const std::string_view energy_docs[] = {
      "the tool's work over the steady part (per the cut's width, like the forces')",
      "of it, dissipated among the integrated disks (friction, broken joints, absorbing layers)",
      "kinetic energy carried off by disks leaving the active window",
      "strain energy carried off by disks leaving the active window",
      "change of the energy stored in the integrated disks"};
  for (std::size_t i = 0; i < std::size(energies); ++i) {
    const auto member = energies[i].second;
    t.push_back(result_if(
        result_value<R>(energies[i].first, "J", energy_docs[i], [member](const R& c) { return c.res.energy.*member; }),
        booked));
  }
}

/// What the edge met over the steady part (CutEdgeRecord, docs/dem.md "What the edge meets"): the shares of the
/// observations in which the tool's boundary within 25 um of its tip touched tied glass, loose fragments or nothing,
/// and the tied share of the disks by depth below the cut line 0.05-0.3 mm ahead of and behind the tip (null without
/// an observation or a disk).
void add_edge_results(ResultTable<R>& t) {
  const auto recorded = [](const R& c) { return c.res.edge_recorded; };
  t.push_back(result_if(result_value<R>(k::edge_observations_steady, "",
                                        "observations of what the tool's edge touched, one per 5 um of steady travel",
                                        [](const R& c) { return c.res.edge.observations; }),
                        recorded));
  t.push_back(
      result_if(result_value<R>(k::edge_touches_tied_share_steady, "",
                                "share of them in which the edge touched glass tied to the workpiece",
                                [](const R& c) { return share(c.res.edge.touches_tied, c.res.edge.observations); }),
                recorded));
  t.push_back(result_if(
      result_value<R>(k::edge_touches_loose_share_steady, "", "share in which it touched loose fragments only",
                      [](const R& c) { return share(c.res.edge.touches_loose, c.res.edge.observations); }),
      recorded));
  t.push_back(result_if(result_value<R>(k::edge_touches_nothing_share_steady, "", "share in which it touched nothing",
                                        [](const R& c) {
                                          const CutEdgeRecord& e = c.res.edge;
                                          return share(e.observations - e.touches_tied - e.touches_loose,
                                                       e.observations);
                                        }),
                        recorded));
  // The tied share's keys follow its stretches and bands (kTiedBandDepthM): generated, like their values.
  static const std::string_view kSide[] = {"ahead", "behind"};
  static const std::string_view kSideDoc[] = {
      "share of the disks still tied to the workpiece 0.05-0.3 mm ahead of the tool, {:g}-{:g} um below the cut line",
      "the same behind the tool (the machined surface), {:g}-{:g} um below the cut line"};
  for (std::size_t side = 0; side < 2; ++side)
    for (std::size_t band = 0; band < 3; ++band) {
      const double from_um = units::m_to_um(kTiedBandDepthM[band]), to_um = units::m_to_um(kTiedBandDepthM[band + 1]);
      t.push_back(result_if(
          result_value<R>(fmt::format("tied_share_{}_depth_{:g}_{:g}_um_steady", kSide[side], from_um, to_um), "",
                          fmt::format(fmt::runtime(kSideDoc[side]), from_um, to_um),
                          [side, band](const R& c) {
                            return share(c.res.edge.profile.tied[side][band], c.res.edge.profile.disks[side][band]);
                          }),
          recorded));
    }
}

/// The edge zone over the steady part (CutEdgeZoneRecord, docs/dem.md "The edge zone"): the share of the samples in
/// which the edge met intact glass, the layer's force, the disks it removed, and the layer's energy (the tool's work
/// on it less what its reaction did on the disks: dissipated below the disks' scale, part of energy_dissipated).
void add_edge_zone_results(ResultTable<R>& t) {
  const auto zone = [](const R& c) { return c.cut.edge_zone.enabled; };
  const auto zone_booked = [](const R& c) { return c.cut.edge_zone.enabled && c.res.energy_booked; };
  t.push_back(result_if(result_value<R>(k::edge_zone_samples_steady, "", "steady samples with the edge zone",
                                        [](const R& c) { return c.res.edge_zone.samples; }),
                        zone));
  t.push_back(result_if(
      result_value<R>(k::edge_zone_intact_share_steady, "",
                      "share of them in which the edge met intact glass (and carried the layer's force)",
                      [](const R& c) {
                        const CutEdgeZoneRecord& z = c.res.edge_zone;
                        return z.samples > 0
                                   ? Json(static_cast<double>(z.intact_samples) / static_cast<double>(z.samples))
                                   : Json();
                      }),
      zone));
  t.push_back(result_if(result_number<R>(k::edge_zone_cutting_force_N_per_mm, units::kNPerMm,
                                         "the ductile layer's cutting force per width",
                                         [](const R& c) { return c.cut.edge_zone.cutting_force_N_per_m; }),
                        zone));
  t.push_back(result_if(
      result_number<R>(k::edge_zone_thrust_force_N_per_mm, units::kNPerMm, "the ductile layer's thrust force per width",
                       [](const R& c) { return c.cut.edge_zone.thrust_force_N_per_m; }),
      zone));
  t.push_back(result_if(
      result_value<R>(k::edge_zone_removed_tied_disks, "", "disks the edge zone removed while tied to the workpiece",
                      [](const R& c) { return c.res.window.chips.edge_tied_disks; }),
      zone));
  t.push_back(result_if(result_value<R>(k::edge_zone_removed_loose_disks, "", "loose disks the edge zone removed",
                                        [](const R& c) { return c.res.window.chips.edge_loose_disks; }),
                        zone));
  t.push_back(result_if(result_value<R>(k::edge_zone_removed_mass_kg, "kg", "their mass, tied and loose",
                                        [](const R& c) {
                                          const ChipAccount& chips = c.res.window.chips;
                                          return chips.edge_tied_mass_kg + chips.edge_loose_mass_kg;
                                        }),
                        zone));
  t.push_back(result_if(
      result_value<R>(k::energy_edge_zone_tool_work_steady_J, "J", "the tool's work on the layer over the steady part",
                      [](const R& c) { return c.res.edge_zone.tool_work_J; }),
      zone_booked));
  t.push_back(result_if(
      result_value<R>(k::energy_edge_zone_reaction_work_steady_J, "J", "the layer's reaction's work on the disks",
                      [](const R& c) { return c.res.edge_zone.reaction_work_J; }),
      zone_booked));
  t.push_back(result_if(
      result_value<R>(k::energy_edge_layer_steady_J, "J",
                      "the layer's own energy: the tool's work less the reaction's (dissipated in it)",
                      [](const R& c) { return c.res.edge_zone.tool_work_J - c.res.edge_zone.reaction_work_J; }),
      zone_booked));
}

}  // namespace

const ResultTable<CutReport>& cut_results() {
  static const ResultTable<CutReport> table = [] {
    ResultTable<R> t;
    add_force_results(t);
    add_cut_results(t);
    add_option_results(t);
    add_edge_results(t);
    add_edge_zone_results(t);
    return t;
  }();
  return table;
}

const ResultTable<TravelWindow>& travel_window_results() {
  namespace w = travel_window_keys;
  using T = TravelWindow;
  // Window ends to 1 pm, so that 3 x 0.1 mm reads 0.3, not 0.30000000000000004.
  static const ResultTable<T> table{
      result_value<T>(w::from_travel_mm, "mm", "where the window starts (tool travel)",
                      [](const T& t) { return std::round(units::m_to_mm(t.from_m) * 1e9) / 1e9; }),
      result_value<T>(w::to_travel_mm, "mm", "where it ends",
                      [](const T& t) { return std::round(units::m_to_mm(t.to_m) * 1e9) / 1e9; }),
      result_value<T>(w::main_force_N, "N", "mean cutting force over the window",
                      [](const T& t) { return t.main_force_N; }),
      result_value<T>(w::thrust_force_N, "N", "mean thrust force over the window",
                      [](const T& t) { return t.thrust_force_N; }),
      result_value<T>(w::samples, "", "samples in the window", [](const T& t) { return t.n_samples; })};
  return table;
}

const ResultTable<CutReport>& active_window_results() {
  namespace a = active_window_keys;
  static const ResultTable<R> table{
      result_value<R>(a::rebuilds, "", "times the window was rebuilt around the tool",
                      [](const R& c) { return c.res.window.rebuilds; }),
      result_value<R>(a::largest_window_particles, "", "the most disks a window held",
                      [](const R& c) { return c.res.window.largest_window_particles; }),
      result_value<R>(a::mean_window_particles, "", "the disks a window held on average (particle-steps / steps)",
                      [](const R& c) {
                        return c.res.particle_steps /
                               (static_cast<double>(c.res.samples.size() - 1) * c.cut.cut.sample_every_steps);
                      }),
      result_value<R>(a::chip_particles_removed, "", "chip disks removed from the integration",
                      [](const R& c) { return c.res.window.chips.particles; }),
      result_value<R>(a::chip_mass_removed_kg, "kg", "their mass",
                      [](const R& c) { return c.res.window.chips.mass_kg; }),
      result_value<R>(a::chip_cracks_removed, "", "crack events of joints with a removed disk at either end",
                      [](const R& c) { return c.res.window.chips.cracks; }),
      // Cracks are found only inside the window and above the workpiece's bottom (a window may reach below it): a
      // damage depth near this is censored.
      result_number<R>(
          a::damage_depth_limit_um, units::kUm,
          "the deepest a crack can be found (the window's floor or the workpiece's bottom): a damage "
          "depth near it is censored",
          [](const R& c) { return std::min(window_box_m(c.cut).below_m, c.res.y_cut_m - c.res.workpiece_box_m[2]); })};
  return table;
}

const std::vector<std::string_view>& cut_replicated_results() {
  static const std::vector<std::string_view> keys{k::main_force_N,
                                                  k::thrust_force_N,
                                                  k::cracks_tensile,
                                                  k::cracks_shear,
                                                  k::subsurface_damage_depth_um,
                                                  k::cracks_subsurface_steady,
                                                  k::subsurface_damage_depth_steady_um,
                                                  k::subsurface_damage_depth_steady_p95_um};
  return keys;
}

namespace {
/// The field of `key` in cut_results().
const ResultField<R>& cut_result(std::string_view key) {
  for (const auto& f : cut_results())
    if (f.key == key) return f;
  throw std::logic_error("cut_result: " + std::string(key) + " is not a cut result");
}
}  // namespace

std::string replicate_spread_key(std::string_view key) {
  const std::string suffix = result_unit_suffix(cut_result(key).unit);
  return std::string(key.substr(0, key.size() - suffix.size())) + "_replicate_std" + suffix;
}

const std::vector<std::string_view>& cut_replicate_row_results() {
  static const std::vector<std::string_view> keys{k::main_force_std_N,   k::thrust_force_std_N, k::main_force_sem_N,
                                                  k::thrust_force_sem_N, k::width_mm,           k::steady,
                                                  k::not_steady_reason};
  return keys;
}

std::string cutting_force_name(std::string_view key) {
  constexpr std::string_view old = "main_force", current = "cutting_force";
  return key.substr(0, old.size()) == old ? std::string(current) + std::string(key.substr(old.size())) : std::string();
}

const ResultTable<CutReport>& cut_derived_results() {
  static const ResultTable<R> table = [] {
    ResultTable<R> t;
    const auto add = [&t](std::string key, std::string_view unit, std::string doc) {
      t.push_back({std::move(key), unit, std::move(doc), {}});
    };
    for (const auto key : cut_replicated_results())
      add(replicate_spread_key(key), cut_result(key).unit,
          fmt::format("with `--replicates`: the spread of `{}` over the replicates (sample std)", key));
    add(std::string(k::main_force_sem_within_cuts_N), "N",
        "with `--replicates`: the error of the mean cutting force from the cuts' own signals, sqrt(sum sem^2) / n "
        "(null when a cut has none)");
    add(std::string(k::thrust_force_sem_within_cuts_N), "N", "the same of the mean thrust force");
    add(std::string(k::cutting_force_N_per_mm), "N/mm",
        fmt::format("`{}` per mm of `{}`", k::cutting_force_N, k::width_mm));
    add(std::string(k::thrust_force_N_per_mm), "N/mm",
        fmt::format("`{}` per mm of `{}`", k::thrust_force_N, k::width_mm));
    // Every main_force_* result, the table's and those above, under its current name.
    ResultTable<R> current;
    const ResultTable<R>* parts[] = {&cut_results(), &t};
    for (const auto* part : parts)
      for (const auto& f : *part)
        if (std::string name = cutting_force_name(f.key); !name.empty()) {
          auto& g = current.emplace_back();
          g.key = std::move(name), g.unit = f.unit;
          g.doc = fmt::format("`{}` under its current name (`main_force_*`: deprecated, until 0.3.0)", f.key);
        }
    t.insert(t.end(), current.begin(), current.end());
    return t;
  }();
  return table;
}

std::vector<std::string> cut_result_names() {
  std::vector<std::string> names = result_keys(cut_results());
  for (auto& key : result_keys(cut_derived_results())) names.push_back(std::move(key));
  return names;
}

}  // namespace kerf::dem
