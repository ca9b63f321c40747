// The scene's Contact subsection: the barrier (distance d_hat, stiffness
// kappa), friction smoothing, and up to four rigid obstacles (plane, sphere,
// meshed surface), each with a rigid motion in time (a displacement and a
// rotation about its point) and a friction coefficient.
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  enum class ObstacleType
  {
    none,
    plane,
    sphere,
    mesh
  };

  struct ObstacleParameters
  {
    /// "Contact/Obstacle k", for messages.
    std::string         subsection;
    unsigned int        number = 0; ///< k
    ObstacleType        type   = ObstacleType::none;
    std::vector<double> point;  ///< plane: a point on it; sphere: its centre
    std::vector<double> normal; ///< plane: unit normal towards the body
    double              radius = 1.;
    std::string         file;
    /// Displacement of the whole obstacle, one expression of t per axis.
    std::vector<std::string> motion;
    /// The axis of the obstacle's rotation about its Point (displaced by
    /// Motion), normalised: 3D its 3 components, 2D one value, the sign of
    /// the out-of-plane axis (+1: counter-clockwise for a positive angle);
    /// empty: the obstacle does not turn.
    std::vector<double> rotation_axis;
    /// The rotation angle in radians, an expression of t ("0" without an
    /// axis).
    std::string rotation_angle = "0";
    double      friction       = 0.;
  };

  struct ContactParameters
  {
    static constexpr unsigned int max_obstacles = 4;
    /// d_hat; 0: automatic (1e-3 of the mesh's bounding-box diagonal).
    double barrier_distance = 0.;
    /// kappa; 0: automatic ((lambda + 2 mu) / d_hat).
    double barrier_stiffness = 0.;
    /// 'Barrier stiffness rule': the automatic kappa at the barrier's
    /// operating point (start from the element size, re-targeted between
    /// steps: BarrierStiffness) rather than (lambda + 2 mu) / d_hat fixed.
    bool operating_point = false;
    /// eps (quasi-static, a slip length) or eps_v (dynamics, a slip
    /// velocity); 0: automatic.
    double       friction_smoothing       = 0.;
    unsigned int friction_lagging_updates = 4;
    /// 'Friction lag trigger = friction force': an update where the
    /// assembled friction force changes (FrictionLagging), rather than
    /// where any single pair's normal force does.
    bool friction_force_trigger = false;
    /// Contact between parts of the body's boundary (and between bodies).
    bool self_contact = false;
    /// mu of the friction between parts of the boundary (self contact).
    double self_contact_friction = 0.;
    /// Meshed obstacles: their sharp vertices against the body's boundary
    /// faces and their sharp edges against its edges, besides the body's
    /// vertices against their surfaces.
    bool meshed_obstacle_corners = true;
    /// The obstacles whose Type is not none, in the order of their sections.
    std::vector<ObstacleParameters> obstacles;

    bool
    active() const
    {
      return !obstacles.empty() || self_contact;
    }

    /// Whether an obstacle or the self contact has friction.
    bool
    has_friction() const
    {
      for (const ObstacleParameters &o : obstacles)
        if (o.friction > 0.)
          return true;
      return self_contact && self_contact_friction > 0.;
    }

    static void
    declare(ParameterHandler &prm);
    /// Relative obstacle files are read from @p scene_folder.
    void
    parse(ParameterHandler &prm, const std::string &scene_folder);
    /// The checks that need the dimension (number of coordinates and
    /// expressions; a 2D scene may leave a third coordinate at 0).
    void
    check(unsigned int dim);
  };
} // namespace hyperelastic
