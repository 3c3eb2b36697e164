#include "solve/NodeOrdering.h"

#include <metis.h>

#include <stdexcept>

namespace rollsim {

namespace {
bool same_pattern(const SparseMatrix& A, int a, int b) {
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const int na = outer[a + 1] - outer[a];
  if (na != outer[b + 1] - outer[b]) return false;
  for (int k = 0; k < na; ++k)
    if (inner[outer[a] + k] != inner[outer[b] + k]) return false;
  return true;
}
}  // namespace

std::vector<int> column_runs(const SparseMatrix& A) {
  std::vector<int> first;
  for (int j = 0; j < A.cols(); ++j)
    if (j == 0 || !same_pattern(A, j - 1, j)) first.push_back(j);
  first.push_back(static_cast<int>(A.cols()));
  return first;
}

namespace {
/// run index of every column
std::vector<int> run_of_columns(const std::vector<int>& first, long cols) {
  std::vector<int> run(static_cast<size_t>(cols));
  for (size_t r = 0; r + 1 < first.size(); ++r)
    for (int j = first[r]; j < first[r + 1]; ++j) run[static_cast<size_t>(j)] = static_cast<int>(r);
  return run;
}

/// distinct runs among the rows of column j (sorted rows: a run's rows are consecutive)
template <class Visit>
void for_each_neighbour_run(const SparseMatrix& A, int j, const std::vector<int>& run_of, Visit visit) {
  int last = -1;
  for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
    const int s = run_of[static_cast<size_t>(it.row())];
    if (s != last) visit(s);
    last = s;
  }
}
}  // namespace

double mean_node_degree(const SparseMatrix& A) {
  const std::vector<int> first = column_runs(A);
  const std::vector<int> run_of = run_of_columns(first, A.cols());
  const size_t runs = first.size() - 1;
  if (runs == 0) return 0;
  double sum = 0;
  for (size_t r = 0; r < runs; ++r) for_each_neighbour_run(A, first[r], run_of, [&](int) { sum += 1; });
  return sum / static_cast<double>(runs);
}

std::vector<int> node_nested_dissection(const SparseMatrix& A) {
  if (!A.isCompressed()) throw std::invalid_argument("node_nested_dissection needs a compressed matrix");
  const std::vector<int> first = column_runs(A);
  const auto runs = static_cast<idx_t>(first.size() - 1);
  const std::vector<int> run_of = run_of_columns(first, A.cols());
  // the quotient graph: run r's neighbours are the runs of the rows of its first column, less itself
  std::vector<idx_t> xadj{0}, adjncy;
  for (idx_t r = 0; r < runs; ++r) {
    for_each_neighbour_run(A, first[static_cast<size_t>(r)], run_of, [&](int s) {
      if (s != r) adjncy.push_back(s);
    });
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
  }
  std::vector<idx_t> perm(static_cast<size_t>(runs)), iperm(static_cast<size_t>(runs));
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  options[METIS_OPTION_NUMBERING] = 0;
  // one refinement pass per level (default 10) and separators balanced to 1.10 (default 1.20 for an ordering): METIS
  // 24-32 % faster on hexahedral node graphs from 4 000 to 16 000 nodes, the factor's flops within -0.8 … +0.9 %
  // (docs/BENCHMARKS.md, "METIS's options")
  options[METIS_OPTION_NITER] = 1;
  options[METIS_OPTION_UFACTOR] = 100;
  idx_t n = runs;
  if (runs > 1 && METIS_NodeND(&n, xadj.data(), adjncy.data(), nullptr, options, perm.data(), iperm.data()) != METIS_OK)
    throw std::runtime_error("METIS_NodeND failed on the node graph");
  if (runs == 1) perm[0] = 0;
  std::vector<int> out;
  out.reserve(static_cast<size_t>(A.cols()));
  for (idx_t k = 0; k < runs; ++k)
    for (int j = first[perm[static_cast<size_t>(k)]]; j < first[perm[static_cast<size_t>(k)] + 1]; ++j)
      out.push_back(j);
  return out;
}

}  // namespace rollsim
