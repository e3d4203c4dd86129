// The fold of a viscoelastic row's let-go branch located between springs: the critical point a
// doubling of the springs converges on, so that Richardson and rtol can extrapolate it.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "engine/model/contact_snapshot.hpp"
#include "engine/program/viscoelastic_jumps.hpp"
#include "engine/program/viscoelastic_row.hpp"
#include "engine/result/run_result.hpp"

namespace mdrsim {

/// The let-gos that began the last cascades of a stage, each with the held value of the normal
/// control (a_u d + a_F F) at which it came. The row's critical point is the equilibrium before
/// the let-go that starts the cascade: it sits on a spring, the same spring of every row of a
/// doubling sequence (under fixed grips each spring lets go at a depth of its own radius), so
/// the rows agree on a value O(dx) off that their changes cannot show. The held value at the
/// let-go of spring n is a smooth function of its radius along the branch, and the continuum's
/// fold is its extremum: the parabola through the held values of springs n + 2, n + 1 and n (n
/// the cascade's first) locates it between springs, within half a spacing of spring n, and the
/// three equilibria before those let-gos are interpolated there (as ProgramFront::fold does for
/// an elastic program's row, with the row's own let-gos in place of a root-found one). What is
/// left is the row's smooth O(dx) error (its force a sum over springs), which extrapolation
/// across rows removes.
///
/// Locates nothing where the branch is not that simple: fewer than three single let-gos of
/// consecutive springs in the stage before the cascade (a fixed load whose cascade starts at its
/// first let-go), a let-go broken at rest by shear, any other change of the row between them, a
/// held value that does not turn there (a constant held force: no fold in it).
class ViscoelasticFold {
 public:
  /// A change of the row in stage `stage`: for a let-go, `before` is the equilibrium it left and
  /// `held` the normal control's held value there.
  void change(ViscoelasticRowChange change, std::string_view stage,
              const ViscoelasticRowSample& before, double held, bool by_shear);
  /// The critical point of the cascade `loss` (the one that lost the glue) between springs, or
  /// nothing; with how far rounding can move each of its fields (force, depth, held value,
  /// radius, time). The held values are rounded (their times, roots in a clock that has run for
  /// the whole program, to its last bits, times the rate of the held value), and their turn
  /// over three springs, h'' dx^2, falls with the spacing squared: the place found between
  /// springs moves by rounding / h'' dx^2 spacings, and a field by that times its change per
  /// spacing, which grows like N. Past the rows where it reaches rtol more springs cannot
  /// locate the fold better.
  struct Located {
    ContactSnapshot state;
    ContactSnapshot rounding;
  };
  std::optional<Located> located(const ViscoelasticCascade& loss) const;
  /// Sets `r`'s refined_critical and its rounding from located(loss) where there is one.
  void locate(const ViscoelasticCascade& loss, RunResult& r) const;

 private:
  struct LetGoPoint {
    std::int64_t spring;  ///< the spring that let go (glued springs before it)
    double held;          ///< the normal control's held value
    ViscoelasticRowSample before;
  };
  std::array<LetGoPoint, 3> trail_{};
  int size_ = 0;
  std::string stage_;
  /// The last let-go began a cascade of more than one let-go.
  bool cascaded_ = false;
  double last_let_go_ = -HUGE_VAL;  ///< the time of the last let-go [s]
};

}  // namespace mdrsim
