// The L1 fit as a linear program: one equality row per stroke voxel,
//   sum_k a_jk w_k - u_j + v_j = s_j,  w, u, v >= 0,  minimize sum_j (u_j + v_j),
// so u_j + v_j = |h_j - s_j| at the optimum. Starting from the basis of all v (w = 0, v = s >= 0)
// the primal simplex begins feasible.
#include "edit_lp.h"

#include <glpk.h>

#include <algorithm>
#include <memory>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

struct ProblemDeleter {
  void operator()(glp_prob* problem) const { glp_delete_prob(problem); }
};

// Silences GLPK's terminal output while alive (it prints to stdout by default).
class QuietGlpk {
 public:
  QuietGlpk() : previous_(glp_term_out(GLP_OFF)) {}
  ~QuietGlpk() { glp_term_out(previous_); }
  QuietGlpk(const QuietGlpk&) = delete;
  QuietGlpk& operator=(const QuietGlpk&) = delete;

 private:
  int previous_;
};

}  // namespace

std::vector<double> solveNonNegativeL1(const std::vector<double>& a, const std::vector<double>& s, int cols) {
  const int rows = int(s.size());
  TS_CHECK(cols >= 1 && rows >= 1 && a.size() == std::size_t(rows) * std::size_t(cols));
  const QuietGlpk quiet;
  std::unique_ptr<glp_prob, ProblemDeleter> problem(glp_create_prob());
  glp_prob* lp = problem.get();
  glp_set_obj_dir(lp, GLP_MIN);
  glp_add_rows(lp, rows);
  glp_add_cols(lp, cols + 2 * rows);  // w_1..w_cols, then u_j, v_j per row
  for (int j = 1; j <= rows; ++j) glp_set_row_bnds(lp, j, GLP_FX, s[std::size_t(j - 1)], s[std::size_t(j - 1)]);
  for (int c = 1; c <= cols + 2 * rows; ++c) {
    glp_set_col_bnds(lp, c, GLP_LO, 0.0, 0.0);
    glp_set_obj_coef(lp, c, c > cols ? 1.0 : 0.0);
  }
  // Column-wise matrix (GLPK arrays are 1-based: element 0 unused).
  std::vector<int> index(std::size_t(rows) + 1);
  std::vector<double> value(std::size_t(rows) + 1);
  for (int j = 1; j <= rows; ++j) index[std::size_t(j)] = j;
  for (int k = 0; k < cols; ++k) {
    for (int j = 0; j < rows; ++j) value[std::size_t(j) + 1] = a[std::size_t(j) * std::size_t(cols) + std::size_t(k)];
    glp_set_mat_col(lp, k + 1, rows, index.data(), value.data());
  }
  for (int j = 1; j <= rows; ++j) {
    int row[2] = {0, j};
    double minus[2] = {0, -1.0}, plus[2] = {0, 1.0};
    glp_set_mat_col(lp, cols + 2 * j - 1, 1, row, minus);
    glp_set_mat_col(lp, cols + 2 * j, 1, row, plus);
  }
  // Feasible start: every v_j basic (v_j = s_j), everything else at its lower bound 0.
  for (int j = 1; j <= rows; ++j) glp_set_row_stat(lp, j, GLP_NS);
  for (int c = 1; c <= cols + 2 * rows; ++c) glp_set_col_stat(lp, c, c > cols && (c - cols) % 2 == 0 ? GLP_BS : GLP_NL);

  glp_smcp parameters;
  glp_init_smcp(&parameters);
  parameters.msg_lev = GLP_MSG_OFF;
  const int status = glp_simplex(lp, &parameters);
  if (status != 0 || glp_get_status(lp) != GLP_OPT)
    throw InternalError("edit linear program: GLPK simplex failed (code " + std::to_string(status) + ", status " +
                        std::to_string(glp_get_status(lp)) + ")");
  std::vector<double> weights(static_cast<std::size_t>(cols));
  for (int k = 0; k < cols; ++k) weights[std::size_t(k)] = std::max(0.0, glp_get_col_prim(lp, k + 1));
  return weights;
}

}  // namespace texsynth
