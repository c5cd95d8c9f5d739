// Result tables: exact headers with units and exact number formatting.
#include "kerf/dem/output/output.hpp"

#include <catch2/catch.hpp>

using namespace kerf::dem;

TEST_CASE("output: crack and curve tables have unit-bearing headers and exact rows", "[output]") {
  const std::vector<CrackEvent> cracks{{2.5e-6, 1e-3, 0.5e-3, 0.0, 10e-6, BreakMode::shear, 7, 1}};
  CHECK(cracks_csv(cracks) ==
        "time_s,x_mm,y_mm,orientation_deg,length_um,mode,bond,element\n"
        "2.5e-06,1,0.5,0,10,shear,7,1\n");
  // A cut's: its place from the cut line (chip above it, subsurface on or below it).
  CHECK(cracks_csv(cracks, 0.4e-3) ==
        "time_s,x_mm,y_mm,orientation_deg,length_um,mode,bond,element,place\n"
        "2.5e-06,1,0.5,0,10,shear,7,1,chip\n");
  CHECK(cracks_csv({}, 0.4e-3) == "time_s,x_mm,y_mm,orientation_deg,length_um,mode,bond,element,place\n");
  LabTestResult r;
  r.curve.push_back({1e-6, 0.001, -0.0002, 5e7, 3, 4});
  CHECK(curve_csv(r) ==
        "time_s,axial_strain,lateral_strain,stress_MPa,tension_cracks,shear_cracks\n"
        "1e-06,0.001,-0.0002,50,3,4\n");
}
