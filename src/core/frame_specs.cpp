#include "sweetspot/frame_specs.hpp"

#include <cmath>
#include <stdexcept>

#include "core/check.hpp"
#include "sweetspot/errors.hpp"

namespace sweetspot {

double fundamental_free_Hz_from_RA(double RA, double frame_mass_kg, double length_m) {
  detail::require_in_range("frame/RA", RA, kMinRA, kMaxRA, "");
  if (!(length_m >= kMinRALength_m && length_m <= kMaxRALength_m)) {
    throw FieldError("frame/RA",
                     "the RA relation is fitted to tennis racquets 27-28 in long (used for " +
                         detail::format_significant(kMinRALength_m / 0.0254) + "-" +
                         detail::format_significant(kMaxRALength_m / 0.0254) +
                         " in); this frame is " + detail::format_significant(length_m / 0.0254) +
                         " in (" + detail::format_significant(length_m * 100.0) +
                         " cm): give frame fundamental_free_Hz or EI_N_m2 instead");
  }
  if (!std::isfinite(frame_mass_kg) || frame_mass_kg < kMinRAFrameMass_kg ||
      frame_mass_kg > kMaxRAFrameMass_kg) {
    throw FieldError("frame/RA",
                     "the RA relation is fitted to tennis racquets of 242-349 g (used for " +
                         detail::format_number(kMinRAFrameMass_kg * 1e3) + "-" +
                         detail::format_number(kMaxRAFrameMass_kg * 1e3) + " g); this frame is " +
                         detail::format_significant(frame_mass_kg * 1e3) +
                         " g: give frame fundamental_free_Hz or EI_N_m2 instead");
  }
  return kRAFitReference_Hz * std::pow(RA / kRAFitReferenceRA, kRAFitRAExponent) *
         std::pow(frame_mass_kg / kRAFitReferenceMass_kg, kRAFitMassExponent);
}

}  // namespace sweetspot
