// Factory for the sparse symmetric factorizations by name ("skyline", "cholmod").
#include "solve/Factorization.h"

#include "solve/CholmodFactorization.h"
#include "solve/SkylineFactorization.h"

namespace rollsim {

std::unique_ptr<Factorization> make_factorization(const std::string& kind) {
  if (kind == "skyline") return std::make_unique<SkylineFactorization>();
  if (kind == "cholmod") return std::make_unique<CholmodFactorization>();
  throw std::invalid_argument("unknown factorization '" + kind + "' (valid: skyline, cholmod)");
}

}  // namespace rollsim
