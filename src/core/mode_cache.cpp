#include "sweetspot/mode_cache.hpp"

#include <bit>
#include <cstdint>

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
    add(k.width_m);
    add(k.thickness_m);
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

const ModalOutputs& ModeCache::modal_outputs(const Design& design, double rel_tol) {
  Key key(design);
  key.add(rel_tol);
  if (modal_ && modal_key_ == key.bits()) {
    ++reuses_;
    return *modal_;
  }
  modal_.reset();
  ModalOutputs solved = evaluate_modes(design, rel_tol);  // may throw: nothing is kept
  ++solves_;
  modal_key_ = key.bits();
  return modal_.emplace(std::move(solved));
}

const ResponseModel& ModeCache::response_model(const Design& design,
                                               const ResponseOptions& options) {
  Key key(design);
  key.add(options.support == ResponseOptions::Support::kFree ? 0.0 : 1.0);
  key.add(static_cast<double>(options.modes));
  key.add(options.free_damping_ratio);
  key.add(options.rel_tol);
  if (response_ && response_key_ == key.bits()) {
    ++reuses_;
    return *response_;
  }
  response_.reset();
  ResponseModel solved = sweetspot::response_model(design, options);
  ++solves_;
  response_key_ = key.bits();
  return response_.emplace(std::move(solved));
}

}  // namespace sweetspot
