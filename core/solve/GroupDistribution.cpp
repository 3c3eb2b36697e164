#include "solve/GroupDistribution.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rollsim {

std::vector<Eigen::MatrixXd> shared_kernels(const GroupDistribution& spread, const BlockSystem& sys) {
  const size_t n = sys.groups.size();
  Eigen::VectorXd cols = Eigen::VectorXd::Zero(static_cast<long>(n));
  for (size_t g = 0; g < n; ++g)
    if (spread.holds(g)) cols[static_cast<long>(g)] = static_cast<double>(sys.groups[g].R.cols());
  spread.sum(cols);
  std::vector<Eigen::VectorXd> flat(n);
  for (size_t g = 0; g < n; ++g)
    flat[g] = spread.holds(g)
                  ? Eigen::VectorXd(sys.groups[g].R.reshaped())
                  : Eigen::VectorXd::Zero(sys.groups[g].C.cols() * static_cast<long>(cols[static_cast<long>(g)]));
  share_vectors(spread, flat);
  std::vector<Eigen::MatrixXd> kernels(n);
  for (size_t g = 0; g < n; ++g)
    kernels[g] = flat[g].reshaped(sys.groups[g].C.cols(), static_cast<long>(cols[static_cast<long>(g)]));
  return kernels;
}

void share_vectors(const GroupDistribution& spread, std::vector<Eigen::VectorXd>& per_group) {
  long size = 0;
  for (const Eigen::VectorXd& x : per_group) size += x.size();
  Eigen::VectorXd all(size);
  long at = 0;
  for (const Eigen::VectorXd& x : per_group) {
    all.segment(at, x.size()) = x;
    at += x.size();
  }
  spread.sum(all);
  at = 0;
  for (Eigen::VectorXd& x : per_group) {
    x = all.segment(at, x.size());
    at += x.size();
  }
}

void throw_first_failure(const GroupDistribution* spread, const std::vector<SingularMatrix>& failed) {
  Eigen::VectorXd flags = Eigen::VectorXd::Zero(static_cast<long>(failed.size()));
  for (size_t g = 0; g < failed.size(); ++g) flags[static_cast<long>(g)] = *failed[g].what() ? 1 : 0;
  if (spread) spread->sum(flags);
  long g = 0;
  while (g < flags.size() && flags[g] == 0) ++g;
  if (g == flags.size()) return;
  const SingularMatrix& mine = failed[static_cast<size_t>(g)];
  if (!spread) throw mine;
  // the message and the column, as numbers, from the holder (the others add zeros)
  constexpr long kLength = 400;
  Eigen::VectorXd text = Eigen::VectorXd::Zero(kLength + 1);
  if (spread->holds(static_cast<size_t>(g))) {
    const std::string what = mine.what();
    for (long i = 0; i < std::min<long>(kLength, static_cast<long>(what.size())); ++i)
      text[i] = static_cast<unsigned char>(what[static_cast<size_t>(i)]);
    text[kLength] = mine.column;
  }
  spread->sum(text);
  std::string what;
  for (long i = 0; i < kLength && text[i] != 0; ++i) what += static_cast<char>(text[i]);
  throw SingularMatrix(what, static_cast<int>(text[kLength]));
}

void refuse_idle_processes(const GroupDistribution& spread, size_t groups) {
  const int P = spread.processes();
  if (static_cast<size_t>(P) <= groups) return;
  const std::string G = std::to_string(groups);
  throw std::invalid_argument("petsc (mixed): " + std::to_string(P) + " MPI ranks for " + G +
                              " groups (bodies and subdomains): the mixed method gives each rank whole groups, so "
                              "ranks " +
                              G + " to " + std::to_string(P - 1) + " would hold none — start it with mpirun -n " + G +
                              " or fewer, tear a body into more subdomains (process.slab_partition, a body's "
                              "partition), or use --petsc-method mumps, which takes any number of ranks");
}

}  // namespace rollsim
