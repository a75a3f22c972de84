#pragma once

// The exact free-free solver: transfer matrices of the closed-form solution
// in each uniform segment. Internal to the beam-mode solvers.

#include "core/beam_modes/segmentation.hpp"

namespace sweetspot::beam_detail {

// The first options.modes free modes, exact to ~1e-12; when the scan may
// have skipped a nearly repeated pair (a finite-element count says so) the
// finite elements answer instead, saying so in the message.
ModalResult exact_free_modes(const Segmentation& seg, const ModeOptions& options);

}  // namespace sweetspot::beam_detail
