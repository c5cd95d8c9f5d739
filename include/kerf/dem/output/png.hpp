#pragma once
// A PNG picture of a specimen (PLplot, cairo driver): disks in grey outline, cracks as short segments
// along the broken interface, red for tension and blue for shear; walls (platens, the cutting tool) as
// black lines. Written whole or not at all.
//
//   write_specimen_png("out/specimen.png", sim, "compression, final state");
//   write_cut_forces_png("out/forces.png", cut_result);   // force against tool travel, the means
//   write_stress_strain_png("out/curve.png", test_result, "compression");
//   write_load_deflection_png("out/curve.png", {toughness_result}, "toughness");  // SENB load against deflection
#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/dem/procedures/lab_test.hpp"
#include "kerf/dem/procedures/toughness.hpp"

namespace kerf::dem {

/// `view_m` (x0, x1, y0, y1): the region shown; default: the disks' extent (a cut's flying fragments would
/// shrink the workpiece to a few pixels, so the cut passes the workpiece's region).
void write_specimen_png(const std::filesystem::path& path, const Simulation& sim, const std::string& title,
                        const std::optional<std::array<double, 4>>& view_m = std::nullopt);

/// Main and thrust force against tool travel (the samples of forces.csv), with the means as dashed lines over
/// the travel they cover, labelled with it, and "NOT STEADY" (also in the title) when CutResult::steady is false.
void write_cut_forces_png(const std::filesystem::path& path, const CutResult& result);

/// A tension or compression test's stress against axial strain (curve.csv), with the secant E over its fit
/// range (0 to 50 % of the peak) and the peak marked.
void write_stress_strain_png(const std::filesystem::path& path, const LabTestResult& result, const std::string& title);

/// Fracture-toughness tests' load against load-point deflection (curve.csv), one line per packing, each peak
/// marked (the first packing's labelled with K_IC).
void write_load_deflection_png(const std::filesystem::path& path, const std::vector<ToughnessResult>& results,
                               const std::string& title);

}  // namespace kerf::dem
