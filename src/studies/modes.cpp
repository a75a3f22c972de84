#include "studies/modes.hpp"

#include <stdexcept>

#include "sweetspot/errors.hpp"
#include "sweetspot/frame_modes.hpp"

namespace sweetspot::studies {

ModesData compute_modes(const io::DesignFile& file, int modes, double rel_tol,
                        ModeOptions::Method method) {
  try {
    const Support::Kind kind = file.design.support.kind;
    if (kind == Support::Kind::kHeadClamped || kind == Support::Kind::kRigidSurface) {
      throw FieldError("support", kind == Support::Kind::kRigidSurface
                                      ? "a rigid surface has no implement, so no modes"
                                      : "the head-clamped frame is held still whole: it has no "
                                        "modes in the model (the strings' ring is "
                                        "string_bed_ring_Hz)");
    }
    const FlexibleFrame frame = flexible_frame(file.design);
    ModeOptions options = frame.options;
    options.modes = modes;
    options.rel_tol = rel_tol;
    options.shape_samples = kShapeSamples;
    if (options.theory == ModeOptions::Theory::kEulerBernoulli) options.method = method;
    // The report reads only the COPs, which need no COR: a COR to be derived (cor_rigid) is not
    // asked for.
    Design rigid = file.design;
    rigid.cor_rigid.reset();
    const std::optional<BeamSupport> rig = beam_support(file.design);
    // The rig's implement's centres of percussion are not shown (a player's);
    // the free modes stand beside the rig's.
    rigid.support = {};
    ModesData data{file,
                   evaluate(rigid),
                   free_modes(frame.sections, frame.point_masses, options),
                   {},
                   {},
                   std::nullopt,
                   frame.mass_distribution_fitted};
    if (rig) {
      options.method = ModeOptions::Method::kFiniteElement;
      data.rig = supported_modes(frame.sections, frame.point_masses, *rig, options);
    } else if (file.design.hand.mass_kg > 0.0) {
      options.method = ModeOptions::Method::kFiniteElement;
      options.modes = modes + 2;  // room for the hand rocking on the grip
      data.held =
          hand_held_modes(frame.sections, frame.point_masses, hand_coupling(file.design), options);
      if (const Mode* fundamental = hand_held_fundamental(data.held))
        data.held_fundamental = *fundamental;
    }
    return data;
  } catch (const std::invalid_argument& e) {
    rethrow_in(file, e);
  }
}

}  // namespace sweetspot::studies
