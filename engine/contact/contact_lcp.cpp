#include "engine/contact/contact_lcp.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "engine/errors.hpp"
#include "engine/tolerances.hpp"

namespace blockfrag {

std::optional<double> solve_single(double a, double d) {
  // FullPivLU's rank test of a 1 x 1 matrix: its pivot above the pivot's size times epsilon
  // (false for 0, infinity and NaN alike).
  const double size = std::abs(a);
  if (!(size > size * std::numeric_limits<double>::epsilon())) return std::nullopt;
  // Its triangular solve divides only a right-hand side that is not zero, keeping a zero's sign.
  return d != 0.0 ? d / a : d;
}

std::optional<std::array<double, 2>> solve_pair(const std::array<std::array<double, 2>, 2>& a,
                                                const std::array<double, 2>& d) {
  for (const auto& row : a) {
    if (!std::isfinite(row[0]) || !std::isfinite(row[1])) return std::nullopt;
  }
  const auto at = [&](int r, int c) {
    return a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
  };
  // The pivot: the first largest in column-major order, as Eigen's maxCoeff visits.
  int pr = 0, pc = 0;
  double best = std::abs(at(0, 0));
  for (const auto& [r, c] : {std::pair{1, 0}, std::pair{0, 1}, std::pair{1, 1}}) {
    if (std::abs(at(r, c)) > best) best = std::abs(at(r, c)), pr = r, pc = c;
  }
  if (best == 0.0) return std::nullopt;
  const double pivot = at(pr, pc), u01 = at(pr, 1 - pc);
  const double l = at(1 - pr, pc) / pivot;
  const double u11 = at(1 - pr, 1 - pc) - l * u01;
  // The rank test: both pivots above the larger's size times the diagonal size times epsilon.
  const double threshold =
      std::max(best, std::abs(u11)) * (2.0 * std::numeric_limits<double>::epsilon());
  if (!(std::abs(u11) > threshold) || !(best > threshold)) return std::nullopt;
  // The triangular solves, each skipping a zero right-hand side as Eigen's does.
  double c0 = d[static_cast<std::size_t>(pr)], c1 = d[static_cast<std::size_t>(1 - pr)];
  if (c0 != 0.0) c1 -= c0 * l;
  if (c1 != 0.0) {
    c1 /= u11;
    c0 -= c1 * u01;
  }
  if (c0 != 0.0) c0 /= pivot;
  return pc == 0 ? std::array{c0, c1} : std::array{c1, c0};
}

namespace {

// More contacts than this would make trying every choice (4^n) too slow to be exact.
constexpr std::size_t kMaxContacts = 6;

// A force direction in lambda = (lambda_n, lambda_t) of one contact: (1, +mu) and (1, -mu) span
// the cone of a sticking contact, (1, -s mu) is a slip's.
struct Column {
  std::size_t contact;
  double tangent;  // lambda_t per lambda_n
};

std::vector<ContactState> allowed_states(const LcpContact& c) {
  if (c.forced_slip != 0) {
    return {c.forced_slip > 0 ? ContactState::slip_positive : ContactState::slip_negative,
            ContactState::off};
  }
  return {ContactState::stick, ContactState::slip_positive, ContactState::slip_negative,
          ContactState::off};
}

// The preference order: fewest contacts not sticking, then fewest off, then the contacts' order.
std::vector<std::vector<ContactState>> choices_in_order(const LcpProblem& p) {
  // One contact's allowed states already come in this order (a landing corner, a pivot): most
  // problems on a seat, spared the products and the sort below.
  if (p.contacts.size() == 1) {
    std::vector<std::vector<ContactState>> single;
    for (const ContactState s : allowed_states(p.contacts.front())) single.push_back({s});
    return single;
  }
  std::vector<std::vector<ContactState>> choices{{}};
  for (const LcpContact& c : p.contacts) {
    std::vector<std::vector<ContactState>> longer;
    for (const auto& prefix : choices) {
      for (const ContactState s : allowed_states(c)) {
        longer.push_back(prefix);
        longer.back().push_back(s);
      }
    }
    choices = std::move(longer);
  }
  // Sorted on (not sticking, off, position in the list): the position as the last key keeps the
  // contacts' order among equals as stable_sort would, without its temporary buffer, whose
  // allocation AddressSanitizer reports as mismatched with Debian 12's libstdc++.
  // Each key computed once, not in every comparison: the keys are distinct, so the order is the
  // same.
  std::vector<std::tuple<int, int, std::size_t>> keys(choices.size());
  for (std::size_t i = 0; i < choices.size(); ++i) {
    int not_sticking = 0, off = 0;
    for (const ContactState s : choices[i]) {
      not_sticking += s != ContactState::stick;
      off += s == ContactState::off;
    }
    keys[i] = {not_sticking, off, i};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::vector<ContactState>> sorted;
  sorted.reserve(choices.size());
  for (const auto& [not_sticking, off, i] : keys) sorted.push_back(std::move(choices[i]));
  return sorted;
}

// At most kMaxContacts contacts: two rows and two columns each. Matrices of this bounded size live
// on the stack: trying every choice allocates nothing per choice.
constexpr int kMaxSize = 2 * static_cast<int>(kMaxContacts);
using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSize, kMaxSize>;
using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSize, 1>;
using Jacobian = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxSize, 3>;

}  // namespace

// What a choice decomposes (LcpDecompositions): its rows' least-squares reach where it has more
// than three, its square system's LU and the full-rank column subsets of a singular one, each
// found when first needed, in the order the search needs them.
struct ChoiceDecomposition {
  struct Subset {
    Matrix columns;
    std::array<Eigen::Index, kMaxSize> used{};
    int count = 0;
    Eigen::ColPivHouseholderQR<Matrix> qr;
    // The QR's solve written out as a matrix, once the subset is asked again (a kept series of
    // problems: the rest range's search), with its and its columns' infinity norms; kept only
    // where the columns' condition (the QR's diagonal's spread) is below kMaxScreenedCondition, so
    // that a product with it is the QR's solve to within 1e-12 of its size.
    std::optional<Matrix> solve_matrix;
    double solve_norm = 0.0, columns_norm = 0.0;
    int asked = 0;
    bool screened = true;

    // Whether the QR's solution for d would surely fail the subset's checks (a residual above the
    // tolerance or an amount below -tolerance): the matrix's answer fails them by more than
    // kClearlyFailing of its size, some 450 times its error at the worst condition screened. Only
    // then is the solve skipped, so a subset that passes, or might, is solved as before: the same
    // solutions to the bit.
    bool clearly_fails(const Vector& d, double tolerance) {
      if (++asked < 2 || !screened) return false;
      if (!solve_matrix) {
        const auto diagonal = qr.matrixR().diagonal().head(count).cwiseAbs();
        screened = diagonal.maxCoeff() <= kMaxScreenedCondition * diagonal.minCoeff();
        if (!screened) return false;
        solve_matrix = qr.solve(Matrix::Identity(columns.rows(), columns.rows()));
        solve_norm = solve_matrix->cwiseAbs().rowwise().sum().maxCoeff();
        columns_norm = columns.cwiseAbs().rowwise().sum().maxCoeff();
      }
      // Written out: Eigen's products of these small dynamic matrices cost more than their sums.
      const Eigen::Index k = columns.rows();
      double d_size = 0.0;
      for (Eigen::Index r = 0; r < k; ++r) d_size = std::max(d_size, std::abs(d(r)));
      const double error = kClearlyFailing * (1.0 + solve_norm * d_size);
      std::array<double, kMaxSize> part{};
      for (int col = 0; col < count; ++col) {
        double sum = 0.0;
        for (Eigen::Index r = 0; r < k; ++r) sum += (*solve_matrix)(col, r) * d(r);
        if (sum < -tolerance - error) return true;
        part[static_cast<std::size_t>(col)] = sum;
      }
      const double residual_limit = tolerance + (1.0 + columns_norm) * error;
      for (Eigen::Index r = 0; r < k; ++r) {
        double sum = -d(r);
        for (int col = 0; col < count; ++col)
          sum += columns(r, col) * part[static_cast<std::size_t>(col)];
        if (std::abs(sum) > residual_limit) return true;
      }
      return false;
    }
  };
  Jacobian j;
  Matrix a;
  bool pinned = false;
  std::optional<Eigen::ColPivHouseholderQR<Jacobian>> reach;
  std::optional<Eigen::FullPivLU<Matrix>> lu;
  std::vector<Subset> subsets;
  unsigned next_mask = 1;  // the first subset of columns not yet looked at
};

namespace {

class Choice {
 public:
  Choice(const LcpProblem& p, const std::vector<ContactState>& states) : p_(p), states_(states) {
    for (std::size_t i = 0; i < states.size(); ++i) {
      const ContactState s = states[i];
      if (s == ContactState::off) continue;
      rows_[rows_count_++] = {i, true};
      if (s == ContactState::stick) {
        rows_[rows_count_++] = {i, false};
        columns_[columns_count_++] = {i, p.friction};
        columns_[columns_count_++] = {i, -p.friction};
      } else {
        columns_[columns_count_++] = {i, -slip_sign(s) * p.friction};
      }
    }
  }

  // The matrices of this choice, which the free accelerations do not change.
  ChoiceDecomposition decompose() const {
    const Eigen::Index k = rows_count_, n = columns_count_;
    ChoiceDecomposition out;
    out.a.resize(k, n);
    out.j.resize(k, 3);
    for (Eigen::Index r = 0; r < k; ++r) {
      const Row& row = rows_[static_cast<std::size_t>(r)];
      const LcpContact& c = p_.contacts[row.contact];
      out.j.row(r) = row.normal ? c.jn : c.jt;
      const Eigen::RowVector3d y_row =
          p_.inertia.inverse_times(out.j.row(r).transpose()).transpose();
      for (Eigen::Index col = 0; col < n; ++col) {
        out.a(r, col) = y_row.dot(generalized(columns_[static_cast<std::size_t>(col)]));
      }
    }
    out.pinned = k > 0 && p_.must_move && pins(out.j);
    // More fixed contact values than the body's three freedoms (as when three contacts hold a
    // block at rest): the body must be able to reach them at all. Checked first, as it rules out
    // most such choices at the cost of one small least-squares solve.
    if (k > 3 && !out.pinned) out.reach.emplace(out.j);
    return out;
  }

  // The contact forces of this choice, if it is consistent.
  std::optional<LcpSolution> solve(ChoiceDecomposition& m) const {
    const Eigen::Index k = rows_count_, n = columns_count_;
    if (k == 0) return check(Vector());
    Vector d(k);
    for (Eigen::Index r = 0; r < k; ++r) {
      const Row& row = rows_[static_cast<std::size_t>(r)];
      const LcpContact& c = p_.contacts[row.contact];
      d(r) = row.normal ? c.target_n - c.free_n : -c.free_t;
    }
    if (m.pinned) return std::nullopt;
    // One slipping contact alone (k = n = 1), one sticking, or two slipping: the LU's
    // decomposition and solve in closed form where the LU would find the system invertible; a
    // singular one is left to the LU's search of redundant rows below.
    if (k == 1) {
      if (const std::optional<double> amount = solve_single(m.a(0, 0), d(0))) {
        return check(Vector::Constant(1, *amount));
      }
    }
    if (k == 2) {
      if (const auto amounts =
              solve_pair({{{m.a(0, 0), m.a(0, 1)}, {m.a(1, 0), m.a(1, 1)}}}, {d(0), d(1)})) {
        Vector x(2);
        x << (*amounts)[0], (*amounts)[1];
        return check(x);
      }
    }
    if (m.reach) {
      const Eigen::Vector3d reach = m.reach->solve(d);
      if ((m.j * reach - d).cwiseAbs().maxCoeff() > p_.tolerance) return std::nullopt;
    }
    // Each stick brings two rows and two columns, each slip one of each: the system is square.
    if (!m.lu) m.lu.emplace(m.a);
    if (m.lu->isInvertible()) return check(m.lu->solve(d));
    // Redundant rows: a non-negative solution, if there is one, lies on rank(A) linearly
    // independent columns (Caratheodory): try those subsets of the cone edges.
    const auto rank = static_cast<int>(m.lu->rank());
    for (std::size_t at = 0; at < m.subsets.size() || next_subset(m, rank); ++at) {
      ChoiceDecomposition::Subset& subset = m.subsets[at];
      if (subset.clearly_fails(d, p_.tolerance)) continue;
      const Vector part = subset.qr.solve(d);
      if ((subset.columns * part - d).cwiseAbs().maxCoeff() > p_.tolerance) continue;
      if (part.minCoeff() < -p_.tolerance) continue;
      Vector full = Vector::Zero(n);
      for (int col = 0; col < subset.count; ++col) {
        full(subset.used[static_cast<std::size_t>(col)]) = part(col);
      }
      if (auto solution = check(full)) return solution;
    }
    return std::nullopt;
  }

 private:
  struct Row {
    std::size_t contact;
    bool normal;
  };

  // Appends the next subset of `rank` columns of m.a whose QR has that rank; false when none is
  // left.
  bool next_subset(ChoiceDecomposition& m, int rank) const {
    const Eigen::Index k = rows_count_, n = columns_count_;
    for (; m.next_mask < (1u << n); ++m.next_mask) {
      const unsigned mask = m.next_mask;
      if (std::popcount(mask) != rank) continue;
      ChoiceDecomposition::Subset subset;
      subset.columns.resize(k, rank);
      for (Eigen::Index col = 0; col < n; ++col) {
        if (mask & (1u << col)) {
          subset.columns.col(subset.count) = m.a.col(col);
          subset.used[static_cast<std::size_t>(subset.count++)] = col;
        }
      }
      subset.qr.compute(subset.columns);
      if (subset.qr.rank() != rank) continue;
      m.subsets.push_back(std::move(subset));
      ++m.next_mask;
      return true;
    }
    return false;
  }

  bool pins(const Jacobian& j) const {
    std::vector<Eigen::RowVector3d> rows;
    for (Eigen::Index r = 0; r < j.rows(); ++r) rows.push_back(j.row(r));
    return pins_body(rows, p_.length);
  }

  Eigen::Vector3d generalized(const Column& col) const {
    const LcpContact& c = p_.contacts[col.contact];
    return c.jn.transpose() + col.tangent * c.jt.transpose();
  }

  std::optional<LcpSolution> check(const Vector& amounts) const {
    const double tol = p_.tolerance;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    for (int col = 0; col < columns_count_; ++col) {
      if (amounts(col) < -tol) return std::nullopt;
      force += std::max(amounts(col), 0.0) * generalized(columns_[static_cast<std::size_t>(col)]);
    }
    const Eigen::Vector3d change = p_.inertia.inverse_times(force);
    for (std::size_t i = 0; i < states_.size(); ++i) {
      const LcpContact& c = p_.contacts[i];
      const double y_n = c.free_n + c.jn.dot(change);
      const double y_t = c.free_t + c.jt.dot(change);
      const int s = slip_sign(states_[i]);
      switch (states_[i]) {
        case ContactState::off:
          if (y_n < c.target_n - tol) return std::nullopt;
          break;
        case ContactState::stick:
          if (std::abs(y_n - c.target_n) > tol || std::abs(y_t) > tol) return std::nullopt;
          break;
        default:
          if (std::abs(y_n - c.target_n) > tol) return std::nullopt;
          if (c.forced_slip == 0 && (c.strict_slip_start ? s * y_t <= 0.0 : s * y_t < -tol)) {
            return std::nullopt;
          }
      }
    }
    LcpSolution out;
    out.states = states_;
    out.normal.assign(states_.size(), 0.0);
    out.tangent.assign(states_.size(), 0.0);
    out.change = change;
    for (int col = 0; col < columns_count_; ++col) {
      // A rounding below zero is zero, so every force lies inside its cone to the last bit.
      const double amount = std::max(amounts(col), 0.0);
      const Column& column = columns_[static_cast<std::size_t>(col)];
      out.normal[column.contact] += amount;
      out.tangent[column.contact] += amount * column.tangent;
    }
    return out;
  }

  const LcpProblem& p_;
  const std::vector<ContactState>& states_;
  std::array<Row, kMaxSize> rows_{};
  std::array<Column, kMaxSize> columns_{};
  int rows_count_ = 0, columns_count_ = 0;
};

double difference(const LcpProblem& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::max({std::abs(a(0) - b(0)), std::abs(a(1) - b(1)), p.length * std::abs(a(2) - b(2))});
}

}  // namespace

bool pins_body(const std::vector<Eigen::RowVector3d>& rows, double length) {
  if (rows.size() < 3) return false;
  Eigen::MatrixXd scaled(static_cast<Eigen::Index>(rows.size()), 3);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    scaled.row(static_cast<Eigen::Index>(i)) =
        rows[i].cwiseProduct(Eigen::RowVector3d(1, 1, 1 / length));
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(scaled);
  lu.setThreshold(kSeatContactDrift);
  return lu.rank() == 3;
}

struct LcpDecompositions::Kept {
  // The shape of the problem they are of: each contact's rows and forced slip, the inertia, the
  // friction, and what decides a pinned choice.
  std::vector<LcpContact> contacts;
  BodyInertia inertia{0.0};
  double friction = 0.0, length = 0.0;
  bool must_move = false;
  std::vector<std::vector<ContactState>> choices;
  std::vector<std::optional<ChoiceDecomposition>> decomposed;  // per choice, once needed

  bool fits(const LcpProblem& p) const {
    const auto same_shape = [](const LcpContact& a, const LcpContact& b) {
      return a.jn == b.jn && a.jt == b.jt && a.forced_slip == b.forced_slip;
    };
    return !choices.empty() && p.friction == friction && p.length == length &&
           p.must_move == must_move && p.inertia.k2 == inertia.k2 && p.inertia.xx == inertia.xx &&
           p.inertia.xtheta == inertia.xtheta && p.inertia.thetatheta == inertia.thetatheta &&
           std::equal(p.contacts.begin(), p.contacts.end(), contacts.begin(), contacts.end(),
                      same_shape);
  }
  void refit(const LcpProblem& p) {
    contacts = p.contacts;
    inertia = p.inertia;
    friction = p.friction;
    length = p.length;
    must_move = p.must_move;
    choices = choices_in_order(p);
    decomposed.assign(choices.size(), std::nullopt);
  }
};

LcpDecompositions::LcpDecompositions() : kept_(std::make_unique<Kept>()) {}
LcpDecompositions::~LcpDecompositions() = default;

namespace {

// The choices of states in preference order, decomposing each once where they are kept.
class ChoiceSearch {
 public:
  ChoiceSearch(const LcpProblem& p, LcpDecompositions::Kept* kept) : p_(p), kept_(kept) {
    if (p.contacts.size() > kMaxContacts) {
      throw ContractViolation("contact problem: more than 6 contacts at once");
    }
    if (kept_ && !kept_->fits(p)) kept_->refit(p);
    if (!kept_) own_ = choices_in_order(p);
  }

  const std::vector<std::vector<ContactState>>& choices() const {
    return kept_ ? kept_->choices : own_;
  }

  std::optional<LcpSolution> solve(std::size_t at) const {
    const Choice choice(p_, choices()[at]);
    if (!kept_) {
      ChoiceDecomposition m = choice.decompose();
      return choice.solve(m);
    }
    std::optional<ChoiceDecomposition>& m = kept_->decomposed[at];
    if (!m) m = choice.decompose();
    return choice.solve(*m);
  }

  // What is chosen where no choice is consistent: no forces.
  LcpSolution none() const {
    LcpSolution out;
    out.states.assign(p_.contacts.size(), ContactState::off);
    out.normal.assign(p_.contacts.size(), 0.0);
    out.tangent.assign(p_.contacts.size(), 0.0);
    out.change.setZero();
    return out;
  }

 private:
  const LcpProblem& p_;
  LcpDecompositions::Kept* kept_;
  std::vector<std::vector<ContactState>> own_;
};

bool slips(const std::vector<ContactState>& states) {
  return std::any_of(states.begin(), states.end(),
                     [](ContactState s) { return slip_sign(s) != 0; });
}

}  // namespace

LcpSolution solve_contact_lcp(const LcpProblem& p, LcpSearch search,
                              LcpDecompositions* decompositions) {
  const ChoiceSearch choices(p, decompositions ? decompositions->kept_.get() : nullptr);
  LcpSolution chosen = choices.none();
  int consistent = 0;
  bool differ = false;
  for (std::size_t at = 0; at < choices.choices().size(); ++at) {
    std::optional<LcpSolution> solution = choices.solve(at);
    if (!solution) continue;
    if (consistent == 0) {
      chosen = *solution;
    } else if (difference(p, solution->change, chosen.change) > kSameContactResult * p.tolerance) {
      differ = true;
    }
    ++consistent;
    // Past this, no choice changes what is chosen or what is known of its determinacy.
    if (differ || search == LcpSearch::first_consistent) break;
  }
  chosen.consistent_choices = consistent;
  chosen.determinacy = consistent == 0 ? Determinacy::inconsistent
                       : differ        ? Determinacy::indeterminate
                                       : Determinacy::unique;
  return chosen;
}

// The choices without a slip first: the first consistent one, c, decides unless a choice with a
// slip comes before it and is consistent, and either way decides false where it fails `still` (a
// slip fails it too). So the choices with a slip are tried only before a c that passes, and only
// until one is consistent. Where none without a slip is consistent, the choice with every contact
// off is not, and what is chosen is no forces, or a choice with a slip.
bool first_consistent_is_still(const LcpProblem& p,
                               const std::function<bool(const LcpSolution&)>& still,
                               LcpDecompositions* decompositions) {
  const ChoiceSearch choices(p, decompositions ? decompositions->kept_.get() : nullptr);
  const std::size_t count = choices.choices().size();
  std::size_t end = count;
  LcpSolution first = choices.none();
  for (std::size_t at = 0; at < count; ++at) {
    if (slips(choices.choices()[at])) continue;
    if (std::optional<LcpSolution> solution = choices.solve(at)) {
      first = *std::move(solution);
      first.consistent_choices = 1;
      first.determinacy = Determinacy::unique;
      end = at;
      break;
    }
  }
  if (!still(first)) return false;
  for (std::size_t at = 0; at < end; ++at) {
    if (slips(choices.choices()[at]) && choices.solve(at)) return false;
  }
  return true;
}

}  // namespace blockfrag
