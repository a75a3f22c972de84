// `sweetspot modes` on a design's support: a rig that lets the frame vibrate
// gives supported_modes()'s modes beside the free ones, the rest are refused.
#include "studies/modes.hpp"

#include <catch2/catch.hpp>
#include <string>

#include "io/design_reader.hpp"
#include "io/input_error.hpp"
#include "sweetspot/frame_modes.hpp"

namespace sweetspot::studies {
namespace {

io::DesignFile lab(const char* name) {
  return io::load_design(std::string(SWEETSPOT_SOURCE_DIR "/designs/lab/") + name);
}

TEST_CASE("On a pivot or with the handle clamped, the modes are supported_modes()'s") {
  for (const char* name : {"pivot-6in.json", "handle-clamped.json"}) {
    INFO(name);
    const io::DesignFile file = lab(name);
    const ModesData data = compute_modes(file, 4, 1e-6, ModeOptions::Method::kExact);
    const FlexibleFrame frame = flexible_frame(file.design);
    ModeOptions options = frame.options;
    options.method = ModeOptions::Method::kFiniteElement;
    options.modes = 4;
    options.rel_tol = 1e-6;
    options.shape_samples = kShapeSamples;
    const ModalResult expected =
        supported_modes(frame.sections, frame.point_masses, *beam_support(file.design), options);
    REQUIRE(data.rig.modes.size() == 4);
    for (std::size_t k = 0; k < 4; ++k)
      CHECK(data.rig.modes[k].frequency_Hz == expected.modes[k].frequency_Hz);
    CHECK(data.held.modes.empty());  // no hand on a rig
    CHECK(data.free.modes.size() == 4);
    // Held, the frame's fundamental is no longer the free one.
    CHECK(data.rig.modes[0].frequency_Hz != data.free.modes[0].frequency_Hz);
  }
}

TEST_CASE("A head clamped whole or a rigid surface has no modes, and says so at /support") {
  for (const char* name : {"head-clamped-strings.json", "ball-on-rigid-surface.json"}) {
    INFO(name);
    try {
      compute_modes(lab(name), 4, 1e-6, ModeOptions::Method::kExact);
      FAIL("no refusal");
    } catch (const io::InputError& e) {
      CHECK(std::string(e.what()).find("/support") != std::string::npos);
    }
  }
}

}  // namespace
}  // namespace sweetspot::studies
