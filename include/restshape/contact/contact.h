// Frictionless one-sided contact with a rigid triangulated obstacle, by a
// primal-dual active set (semismooth Newton) inside the Newton loop.
#ifndef restshape_contact_h
#define restshape_contact_h

#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>

#include <restshape/base/region.h>
#include <restshape/contact/contact_parameters.h>
#include <restshape/contact/held_planes.h>
#include <restshape/contact/obstacle.h>
#include <restshape/fem/discretization.h>
#include <restshape/fem/state_reader.h>
#include <restshape/solver/active_set_constraints.h>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace RestShape
{
  /**
   * Node-to-surface contact. Candidates are the boundary nodes of the
   * contact labels. At every Newton iterate, each candidate i has a signed
   * gap g_i (m, > 0 on the allowed side) and the gap's gradient n_i. A node
   * is active when it is eligible and
   *
   *     p_i - c (g_i - g_tol) > 0,      p_i = lambda_i / A_i,
   *
   * with lambda_i = -r_i . n_i the obstacle's force on an active node (from
   * the raw residual r, N; zero for inactive nodes), A_i the node's lumped
   * (HRZ) area, c = (Active set constant) E_max / h_min. Active nodes get the
   * linearised constraint n_i . delta_i = -g_i (an AffineConstraints line on
   * their dominant free component, general normals allowed). A node resting
   * in a crease of the triangulated obstacle (its closest face alternates)
   * holds the planes of both faces, two constraints, and slides along the
   * crease; in a corner, three.
   *
   * In a forward simulation every candidate is eligible: a node that
   * starts beyond the obstacle is brought onto it. One-sided rule of the
   * inverse iteration (Morin et al. 2015; set_one_sided()): a node is
   * eligible once it has been on the allowed side (g >= -g_tol) during the
   * solve, or once a Newton step carried it through the allowed region and
   * out again; a node that starts a solve on the wrong side is free until
   * then (a rest shape may lie beyond the skull).
   */
  class ContactProblem : public ActiveSetConstraints
  {
  public:
    /// Contact of the body on @p discretization, whose displacement
    /// @p state holds (the forward problem). @p newton_tolerance (relative
    /// residual, Solver/Newton tolerance) sets the gap tolerance,
    /// @p max_youngs_modulus (Pa) the active-set constant.
    ContactProblem(const ContactParameters &parameters,
                   const Discretization    &discretization,
                   const StateReader       &state,
                   const double             newton_tolerance,
                   const double             max_youngs_modulus,
                   dealii::TimerOutput     &timer);
    ~ContactProblem();

    /// Find candidate nodes and their areas (after ForwardProblem::setup()).
    void
    setup();

    /// The obstacle's surface.
    const Obstacle &
    surface() const
    {
      return *obstacle;
    }

    /// A new solve starts from displacement @p d (ghosted).
    void
    begin_solve(const VectorType &d) override;

    /// The one-sided rule of the inverse iteration on (the solves of the
    /// fixed point) or off (forward simulations: the default).
    void
    set_one_sided(const bool on)
    {
      one_sided = on;
    }
    bool
    is_one_sided() const
    {
      return one_sided;
    }

    /**
     * An opening of the obstacle (a craniotomy): the candidates inside
     * @p opening (mesh geometry) lose their contact until close_openings():
     * never eligible or active, never counted beyond the obstacle (tissue may
     * bulge through the opening). Returns how many (all ranks).
     */
    unsigned int
    remove_contact(const Region &opening);
    /// Undo remove_contact(): contact allowed again where it was opened.
    void
    close_openings();
    /// The active and eligible flags of every candidate: saved with an
    /// equilibrium, restored with it when a step is taken back.
    State
    state() const override;
    void
    set_state(const State &state) override;
    /// Forget the active set (a new problem starts).
    void
    reset() override;

    /**
     * Gaps at @p d; eligibility; new active set from the contact forces in
     * @p raw_residual (ignored if @p first_iteration: no node is released).
     * Returns whether the active set changed.
     */
    bool
    update_active_set(const VectorType &d,
                      const VectorType &raw_residual,
                      const bool        first_iteration) override;

    /**
     * The largest step length alpha <= 1 along the Newton update @p delta
     * (owned vector) for which no eligible inactive node goes further than
     * a quarter of the smallest cell beyond the obstacle (linearised gap
     * g + alpha n . delta): a step cannot carry the body through the
     * obstacle; the nodes that reach it are activated at the next iterate.
     */
    double
    max_step(const VectorType &delta) const override;

    /// Add the constraints of the active nodes (not touching @p base's).
    void
    add_constraints(
      dealii::AffineConstraints<double>       &constraints,
      const dealii::AffineConstraints<double> &base) const override;

    /**
     * Called while releases are frozen (cycling, or more than Contact/Free
     * active-set updates in this solve), at the top of a Newton step whose
     * residual is below the load and whose active set did not change, and
     * when Newton has converged: if the
     * active nodes that pull on the obstacle (tensile contact force) carry
     * more than 0.1 % of the total contact force, exactly those are released
     * (they come back only if they go through the obstacle) and true is
     * returned (Newton goes on); at most five times per solve. Nodes that
     * came back (grazing) are held here; the strict check of the converged
     * state (check_conditions(), enforce_conditions()) releases them if
     * they pull beyond its tolerance.
     */
    bool
    thaw_if_adhesive(const VectorType &raw_residual) override;

    /// No eligible node beyond the obstacle and every active node on it
    /// (within g_tol) at the state of the last update.
    bool
    is_satisfied() const override;
    bool
    moves_nodes_onto_surface() const override;

    /**
     * The contact conditions at the displacement @p d (ghosted) with the
     * raw residual @p raw_residual of that state, against the obstacle's
     * surface (ContactConditions). A pull counts if the node's force (or a
     * held plane's) is below -@p force_tolerance (N) and below -Contact/
     * Pull tolerance times the node's area.
     */
    ContactConditions
    check_conditions(const VectorType &d,
                     const VectorType &raw_residual,
                     const double      force_tolerance) const override;

    /**
     * After a Newton solve converged with the conditions @p violated (the
     * heuristics of update_active_set() and thaw_if_adhesive() accept
     * small pulls and hold crease nodes on fixed planes): release every
     * node and held plane that pulls by more than @p force_tolerance
     * (and Contact/Pull tolerance times its area) (grazing nodes too: they come
     * back only through the obstacle), let nodes on fixed planes that left the
     * surface follow it again. Releases stay frozen for the rest of the
     * solve: the nodes released here come back only through the obstacle,
     * and the others are released once Newton has converged (or from
     * |R| <= |f|, thaw_if_adhesive()). Returns whether it changed
     * anything (then Newton goes on).
     */
    bool
    enforce_conditions(const ContactConditions &violated,
                       const VectorType        &raw_residual,
                       const double             force_tolerance) override;

    /**
     * Whether the rounds of enforce_conditions() cycle ("" while they do
     * not, else what repeats): a converged state (active nodes, held
     * planes, violations) came back in a later round of this solve. Newton
     * then fails, and load stepping takes a smaller increment.
     */
    const std::string &
    cycle_text() const override
    {
      return cycle;
    }


    /// Why the contact conditions are not met at the state of the last
    /// update (nodes through the obstacle, active nodes off it, the largest
    /// violation in mm, nodes the last update added or released), for the
    /// message of a Newton solve whose residual met the tolerance when it
    /// ran out of iterations.
    std::string
    unsettled_text() const override;

    /// ", contact N active (+a new, -r released)" for the Newton progress line.
    std::string
    progress_text() const override;

    /// Tolerance on gaps (m): the Newton tolerance times the body's size
    /// (gaps are resolved as tightly as the residual), at least 1e-10 of
    /// the size.
    const double gap_tolerance;

  private:
    // What the contact carries and where (contact_report.h), and the
    // target the obstacle admits (admissible_target.h), read the
    // candidates.
    friend class ContactReport;
    friend class AdmissibleTarget;
    using Plane = ContactPlane;

    struct Candidate
    {
      Node                node;
      std::array<bool, 3> fixed;
      bool                owned;
      double area_lumped = 0; // HRZ over all its boundary faces, m^2
      bool   eligible    = false;
      bool   active      = false;
      bool   pulled      = false; // released by thaw_if_adhesive()
      /// Carried off the surface by its planes: it follows the surface's
      /// distance along their mean normal for the rest of the solve.
      bool follow_surface = false;
      /// While it follows the surface: the gap's change per unit of its
      /// move along the normal, measured between updates (secant; 1 on a
      /// plane normal to it). Its constraint moves it by gap / slope.
      double surface_slope = 1;
      bool   removed       = false; // in an opening (remove_contact())
      bool   opened        = false; // removed by remove_contact()
      bool   set_aside     = false; // by AdmissibleTarget::keep_contacts()
      /// Released for pulling and back through the obstacle in this solve:
      /// it pulls when held and penetrates when free, so it is held and its
      /// pull accepted (not released again in this solve).
      bool                 grazing = false;
      double               gap     = 0;
      dealii::Tensor<1, 3> normal;
      dealii::Point<3>     previous_position;
      /// While releases are frozen: the planes it holds in a crease.
      HeldPlanes   planes;
      unsigned int dropped = 0; // held planes let go (bits; owner, thaw)
      /// For a node on fixed planes: whether they could be imposed at the
      /// last add_constraints() (else their mean plane was).
      mutable bool planes_imposed = true;
    };

    /// Violated contact conditions over all ranks, at the state of the
    /// last update: eligible nodes beyond the obstacle, active nodes off
    /// it (|gap| > g_tol), and the largest |gap| among them (m).
    struct Violations
    {
      unsigned int through = 0, off = 0;
      double       worst = 0;
    };
    Violations
    violations() const;
    /// The mesh's MPI communicator.
    MPI_Comm
    communicator() const;
    /// Owned candidates for which @p predicate holds, summed over the ranks.
    template <typename Predicate>
    unsigned int
    count_owned(const Predicate &predicate) const;

    /// X + d at a node (m).
    static dealii::Point<3>
    position(const Node &node, const VectorType &d);
    dealii::Point<3>
    position(const Candidate &c, const VectorType &d) const;
    /// The obstacle's force on an active node along its normal (N).
    double
    contact_force(const Candidate &c, const VectorType &raw_residual) const;
    /// The obstacle's force on an active node (N): along its normal, or
    /// split among its held planes (their multipliers, in the order of
    /// Candidate::held, in @p multipliers if given).
    dealii::Tensor<1, 3>
    reaction(const Candidate     &c,
             const VectorType    &raw_residual,
             std::vector<double> *multipliers = nullptr) const;
    /// A candidate that may no longer take contact (an opening, a
    /// contact the target does not keep).
    static void
    take_out(Candidate &c);
    /// The candidates taken out for the reason @p why (a flag of theirs)
    /// may take contact again.
    void
    put_back(bool Candidate::*why);
    /// Forget the held planes and locks of a node (a new solve, or a node
    /// that is not active while releases are frozen).
    static void
    let_go(Candidate &c);
    /// The gap the node's constraints use (m): the signed distance to the
    /// obstacle, or for a node on fixed planes the one farthest from 0 (or
    /// the mean plane's, if those were imposed instead).
    static double
    constrained_gap(const Candidate &c);
    /// The pull (N) node @p c may carry in a converged state: the larger
    /// of @p force_tolerance (round-off) and Contact/Pull tolerance times
    /// its area.
    double
    node_force_tolerance(const Candidate &c,
                         const double     force_tolerance) const;
    /// Let go of the held planes whose bits are set in @p mask.
    static void
    drop_planes(Candidate &c, const unsigned int mask);
    /// Add the constraints n_i . delta = -g_i of the planes @p planes of
    /// candidate @p c; false if its free components cannot satisfy them.
    bool
    add_plane_constraints(const Candidate                         &c,
                          const std::vector<Plane>                &planes,
                          dealii::AffineConstraints<double>       &constraints,
                          const dealii::AffineConstraints<double> &base) const;
    void
    share_flags();
    /// The bit of share_flags() for Candidate::follow_surface (above the
    /// active, eligible and dropped-plane bits).
    static constexpr int follow_surface_flag = 32;
    /// Let the node follow the surface along its held planes' mean normal
    /// for the rest of the solve (Candidate::follow_surface).
    static void
    follow_surface(Candidate &c);
    /// Whether the planes node @p c holds carried it off the obstacle's
    /// surface (beyond the gap tolerance): it follows the surface then.
    bool
    carried_off_surface(const Candidate &c) const;
    /// For a node that follows the surface, now at @p x with gap @p gap:
    /// its secant slope from the last update (Candidate::surface_slope).
    static void
    measure_surface_slope(Candidate &c, const dealii::Point<3> &x, double gap);

    const ContactParameters   parameters;
    const Discretization     &discretization;
    const StateReader        &forward_state;
    const double              max_youngs_modulus; // Pa
    dealii::TimerOutput      &timer;
    std::unique_ptr<Obstacle> obstacle;
    /// A boundary face of a contact label: its candidate nodes with, for
    /// each, the HRZ-lumped area and int phi dA (m^2).
    struct Face
    {
      std::vector<unsigned int> nodes;
      std::vector<double>       lumped, integral;
      dealii::Tensor<1, 3>      normal; // outward, mesh geometry
    };

    std::vector<Candidate> candidates;
    std::vector<Face>      faces;
    /// Owned surface faces on cavity walls, left out of the candidates.
    unsigned int          n_cavity_wall_faces = 0;
    double                c_scaled            = 0;
    std::set<std::size_t> history;
    double                h_min           = 0;
    bool                  releases_frozen = false;
    bool                  one_sided       = false;
    /// Constraints changed outside update_active_set() (a thaw, a round
    /// of enforce_conditions()) since the last update.
    bool         constraints_changed = false;
    unsigned int n_updates = 0, n_thaws = 0;
    /// The description of a cycle of enforce_conditions()'s rounds.
    std::string cycle;
    /// Signatures of the converged states of this solve's rounds.
    std::set<std::size_t> rounds;
    /// The active nodes (with their held planes) and the violations.
    std::size_t
                 round_signature(const ContactConditions &violated) const;
    unsigned int n_added = 0, n_released = 0;
  };
} // namespace RestShape

#endif
