#include "analysis/ForcingSequence.h"

#include <algorithm>
#include <cmath>

namespace rollsim {

namespace {
constexpr double kGamma = 0.9, kAlpha = 2.0;  // Eisenstat & Walker's choice 2
constexpr double kSafeguard = 0.1;            // γ η_{k−1}^α above this bounds η_k from below
}  // namespace

ForcingSequence::ForcingSequence(Forcing kind, double loosest, double floor)
    : kind_(kind), loosest_(loosest), floor_(kind == Forcing::Fixed ? loosest : std::min(floor, loosest)) {}

void ForcingSequence::restart() { last_residual_ = last_eta_ = 0; }

InterfaceTolerance ForcingSequence::next(double residual, bool balanced, double enough) {
  // fixed: and, once the residual is balanced and only a check is left to meet, at most `enough` — a relative
  // tolerance of the total multipliers' residual can leave the constraint rows unmet by more than Newton's check
  // accepts. Not before: pushed below what it reaches early in a step, an unpreconditioned interface CG drifted
  // (the 72 x 12 slab in 4 subdomains then cut its first step back six times instead of once).
  if (kind_ == Forcing::Fixed) return {loosest_, 0, false, balanced ? enough : 0.0};
  double eta = balanced ? floor_ : loosest_;
  if (!balanced && last_eta_ > 0 && last_residual_ > 0) {
    eta = kGamma * std::pow(residual / last_residual_, kAlpha);
    const double safeguard = kGamma * std::pow(last_eta_, kAlpha);
    if (safeguard > kSafeguard) eta = std::max(eta, safeguard);
  }
  eta = std::clamp(eta, floor_, loosest_);
  last_residual_ = residual;
  last_eta_ = eta;
  return {eta, enough, true};
}

}  // namespace rollsim
