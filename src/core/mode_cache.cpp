#include "sweetspot/mode_cache.hpp"

#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/frame_solve.hpp"

namespace sweetspot {
namespace {

// Every input the modes depend on, as numbers compared bit for bit: the
// implement (its length, frame mass properties, sections and point masses),
// the frame's stiffness and the hand. An optional is its presence, then its
// value. Two designs with equal keys have the same modes.
class Key {
 public:
  explicit Key(const Design& d) {
    const Implement& implement = d.implement;
    add(implement.length_m());
    const MassProperties& frame = implement.frame_mass_properties();
    add(frame.mass_kg);
    add(frame.com_from_butt_m);
    add(frame.I_cm_kg_m2);
    add(static_cast<double>(implement.sections().size()));
    for (const Section& s : implement.sections()) {
      add(s.length_m);
      add(s.mass_kg);
      add(s.EI_N_m2);
    }
    add(static_cast<double>(implement.round_slices().size()));
    for (const RoundSlice& r : implement.round_slices()) {
      add(r.diameter_m);
      add(r.wall_m);
    }
    add(static_cast<double>(implement.point_masses().size()));
    for (const PointMass& p : implement.point_masses()) {
      add(p.from_butt_m);
      add(p.mass_kg);
      add(p.off_axis_m);
    }
    const FrameStiffness& k = d.stiffness;
    add(k.EI_N_m2);
    add(k.fundamental_free_Hz);
    add(k.RA);
    add(k.shear_modulus_Pa);
    add(static_cast<double>(k.cross_section.shape));
    add(k.cross_section.width_m);
    add(k.cross_section.thickness_m);
    add(k.cross_section.diameter_m);
    add(k.cross_section.wall_m);
    add(k.cross_section.poisson_ratio);
    const Hand& h = d.hand;
    add(h.mass_kg);
    add(h.center_from_butt_m);
    add(h.grip_length_m);
    add(h.grip_stiffness_N_m2);
    add(h.grip_damping_N_s_m2);
  }

  void add(double x) { bits_.push_back(std::bit_cast<std::uint64_t>(x)); }
  void add(const std::optional<double>& x) {
    add(x ? 1.0 : 0.0);
    add(x.value_or(0.0));
  }

  const std::vector<std::uint64_t>& bits() const { return bits_; }

 private:
  std::vector<std::uint64_t> bits_;
};

}  // namespace

const FlexibleFrame& ModeCache::frame(const Design& design, const std::vector<std::uint64_t>& key) {
  if (frame_ && frame_key_ == key) return *frame_;
  frame_.reset();
  FlexibleFrame built = flexible_frame(design);  // may throw: nothing is kept
  frame_key_ = key;
  return frame_.emplace(std::move(built));
}

const ModalOutputs& ModeCache::modal_outputs(const Design& design, double rel_tol) {
  const Key frame_key(design);
  Key key = frame_key;
  key.add(rel_tol);
  if (modal_ && modal_key_ == key.bits()) {
    ++reuses_;
    return *modal_;
  }
  modal_.reset();
  const FlexibleFrame& shared = frame(design, frame_key.bits());
  // The free fundamental of the free response model on this frame, when the
  // exact solver gave it: a second solve would give the same numbers.
  const Mode* free_fundamental =
      response_ && response_free_exact_ && response_frame_key_ == frame_key.bits()
          ? &response_->modes.front().mode
          : nullptr;
  ModalOutputs solved = detail::evaluate_modes_on(design, shared, rel_tol,
                                                  free_fundamental);  // may throw: nothing is kept
  ++solves_;
  modal_key_ = key.bits();
  return modal_.emplace(std::move(solved));
}

const ResponseModel& ModeCache::response_model(const Design& design,
                                               const ResponseOptions& options) {
  const Key frame_key(design);
  Key key = frame_key;
  key.add(static_cast<double>(static_cast<int>(options.support)));
  if (options.support == ResponseOptions::Support::kRig) {
    key.add(static_cast<double>(static_cast<int>(options.rig.kind)));
    key.add(options.rig.from_m);
    key.add(options.rig.to_m);
  }
  key.add(static_cast<double>(options.modes));
  key.add(options.free_damping_ratio);
  key.add(options.rel_tol);
  if (response_ && response_key_ == key.bits()) {
    ++reuses_;
    return *response_;
  }
  response_.reset();
  const std::string why = options.validate();
  if (!why.empty()) throw std::invalid_argument("options." + why);
  const FlexibleFrame& shared = frame(design, frame_key.bits());
  bool exact_free = false;
  ResponseModel solved = detail::response_model_on(design, shared, options, &exact_free);
  ++solves_;
  response_key_ = key.bits();
  response_frame_key_ = frame_key.bits();
  response_free_exact_ = exact_free && options.support == ResponseOptions::Support::kFree;
  return response_.emplace(std::move(solved));
}

}  // namespace sweetspot
