//! Linear multibody models: bodies, rigid and flexible connections, nonholonomic points,
//! loads, actuators and sensors, assembled exactly into the descriptor system
//! $E \dot x = A x + B u$, $y = C x + D u$ (the formulation of Minaker's EoM).
//!
//! Every body has six coordinates at its centre of mass: translation $(x, y, z)$ and a
//! small rotation $(\theta_x, \theta_y, \theta_z)$; the ground is fixed. With $p$ the
//! positions, $w$ the velocities and the inputs $u$ appended to the state,
//!
//! $$\begin{bmatrix} I & 0 & 0 \\ 0 & M & -F_r \\ 0 & 0 & 0 \end{bmatrix}
//! \begin{bmatrix} \dot p \\ \dot w \\ \dot u \end{bmatrix} = -
//! \begin{bmatrix} V & -I & 0 \\ K + K_t + K_l & C + C_m & -F \\ 0 & 0 & I \end{bmatrix}
//! \begin{bmatrix} p \\ w \\ u \end{bmatrix} + \begin{bmatrix} 0 \\ 0 \\ I \end{bmatrix} u$$
//!
//! restricted to the motions the constraints allow: with $J$ the rigid constraint Jacobian
//! and $J_n$ the nonholonomic one, the right basis $R$ spans the null space of
//! $[J, 0; -J V, J; 0, J_n]$, the left basis $L$ that of $[J, 0; 0, J; 0, J_n]$, and
//! $E = L^T \mathcal M R$, $A = -L^T \mathcal K R$, $B = L^T [0; 0; I]$, $C = C_{full} R$.
//! $M$ is the mass matrix, $K = H^T \operatorname{diag}(k) H$ and $C = H^T \operatorname{diag}(c) H$
//! the stiffness and damping of the flexible items ($H$ their deflection Jacobian),
//! $V$ the kinematic velocity terms ($\dot p = w - V p$: a body moving at velocity
//! $v$ has $V = [0, [v]_\times; 0, 0]$), $C_m$ the momentum (centripetal and gyroscopic)
//! terms, $K_t$ the tangent stiffness of the items carrying an equilibrium preload and
//! $K_l$ that of the applied loads; $F$ and $F_r$ the actuators' gains and rate gains.
//!
//! Directions stay rational: a connection carrying forces along (or normal to) an axis
//! $d$ uses $d d^T / (d \cdot d)$ (or $I - d d^T/(d \cdot d)$), a spring along $d$ has
//! stiffness $k\, g^T g / (d \cdot d)$ with $g$ its unnormalised row. The descriptor's
//! states are the free coordinates of the canonical null space bases (names like
//! `chassis.z`, `v.wheel.ry`, `u.z_g`).
//!
//! | entry point | does |
//! |---|---|
//! | [`assemble`] | a [`Model`] over any field `K` -> [`Assembly`] (descriptor + derivation) |
//! | [`chain`] | the `n`-body spring-mass chain used by the benches |
//!
//! The standard form of the assembled descriptor is [`crate::realization::descriptor_to_standard`]
//! (the index-1 elimination when $E$ is block diagonal up to a permutation, as here).

#![allow(non_snake_case)]

mod assemble;
pub mod geometry;
mod preload;

pub use assemble::assemble;
pub use geometry::Vec3;

use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::Descriptor;

/// A rigid body. Inertia is about the centre of mass, as the tensor
/// `[[Ixx, -Ixy, -Izx], [-Ixy, Iyy, -Iyz], [-Izx, -Iyz, Izz]]` with products of inertia
/// $I_{xy} = +\int r_x r_y\,dm$ (EoM's convention).
#[derive(Clone, Debug)]
pub struct Body<K: Field> {
    pub name: String,
    pub mass: K::Elem,
    pub location: Vec3<K>,
    pub inertia: Matrix<K>,
    /// Nominal velocity of the centre of mass (forward speed).
    pub velocity: Vec3<K>,
    /// Nominal angular velocity (a spinning wheel).
    pub angular_velocity: Vec3<K>,
}

/// Which equations a point connection writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointKind {
    /// Position constraint (a joint).
    Rigid,
    /// Stiffness and damping (a bushing, a tire).
    Flexible,
    /// Velocity constraint (rolling without slip).
    Nonholonomic,
}

/// A connection at one point between two bodies (`bodies[i] == nbodies` is the ground).
///
/// `forces` / `moments` say how many directions it carries: 3 (all), 2 (normal to `axis`),
/// 1 (along `axis`), 0.
#[derive(Clone, Debug)]
pub struct PointItem<K: Field> {
    pub name: String,
    pub kind: PointKind,
    pub bodies: [usize; 2],
    pub location: Vec3<K>,
    pub forces: u8,
    pub moments: u8,
    pub axis: Vec3<K>,
    /// Rolling contact: the axis the wheel rolls about (tangent stiffness of the preload).
    pub rolling_axis: Option<Vec3<K>>,
    /// Stiffness for forces and for moments (flexible items).
    pub stiffness: [K::Elem; 2],
    pub damping: [K::Elem; 2],
}

/// What a two-point item is.
#[derive(Clone, Debug)]
pub enum LineKind<K: Field> {
    /// A spring/damper along the line.
    Spring {
        stiffness: K::Elem,
        damping: K::Elem,
    },
    /// A rigid link: the distance is constrained.
    Link,
    /// An input: a force (or a moment with `twist`) `gain * u + rate_gain * u'` along the
    /// line, acting on body 1 (and reacting on body 2).
    Actuator { gain: K::Elem, rate_gain: K::Elem },
    /// An output: `gain` times the motion of body 1 relative to body 2 along the line
    /// (from location 1 to location 2, then negated: EoM's sign), of position (`order` 1),
    /// velocity (2) or acceleration (3, an algebraic state appended per sensor), in the ground frame or the body's own (`local`); minus
    /// `actuator_gain` times input `actuator`.
    Sensor {
        gain: K::Elem,
        order: u8,
        local: bool,
        actuator: Option<(usize, K::Elem)>,
    },
}

/// An item between two points on two bodies.
#[derive(Clone, Debug)]
pub struct LineItem<K: Field> {
    pub name: String,
    pub kind: LineKind<K>,
    pub bodies: [usize; 2],
    pub locations: [Vec3<K>; 2],
    /// Acts on rotations (a torque, an angle) instead of translations.
    pub twist: bool,
}

/// An applied load (a weight): force and moment on `body`, at `location`.
#[derive(Clone, Debug)]
pub struct Load<K: Field> {
    pub name: String,
    pub body: usize,
    pub location: Vec3<K>,
    pub force: Vec3<K>,
    pub moment: Vec3<K>,
}

/// A linear multibody model over the field `K` (`Q`, or `Q(p)` with symbols).
#[derive(Clone, Debug)]
pub struct Model<K: Field> {
    pub field: K,
    pub name: Option<String>,
    pub bodies: Vec<Body<K>>,
    pub points: Vec<PointItem<K>>,
    pub lines: Vec<LineItem<K>>,
    pub loads: Vec<Load<K>>,
}

impl<K: Field> Model<K> {
    /// Location of body `b` (the ground, `b == bodies.len()`, sits at the origin).
    pub fn origin(&self, b: usize) -> Vec3<K> {
        self.bodies
            .get(b)
            .map_or_else(|| geometry::zero3(&self.field), |x| x.location.clone())
    }
    /// The actuators in file order.
    pub fn actuators(&self) -> impl Iterator<Item = &LineItem<K>> {
        self.lines
            .iter()
            .filter(|l| matches!(l.kind, LineKind::Actuator { .. }))
    }
    /// The sensors in file order.
    pub fn sensors(&self) -> impl Iterator<Item = &LineItem<K>> {
        self.lines
            .iter()
            .filter(|l| matches!(l.kind, LineKind::Sensor { .. }))
    }
}

/// The assembled model: the descriptor system and how it was derived.
#[derive(Clone, Debug)]
pub struct Assembly<K: Field> {
    /// $E \dot x = A x + B u$, $y = C x + D u$.
    pub descriptor: Descriptor<K>,
    /// Names of the descriptor's states (the free coordinates of the right basis).
    pub state_names: Vec<String>,
    pub input_names: Vec<String>,
    pub output_names: Vec<String>,
    /// Names of the `6 n` body coordinates (`chassis.x` .. `chassis.rz`).
    pub coordinate_names: Vec<String>,
    pub mass: Matrix<K>,
    pub stiffness: Matrix<K>,
    pub damping: Matrix<K>,
    /// From the equilibrium preload of the connections ($K_t$).
    pub tangent_stiffness: Matrix<K>,
    /// From the applied loads ($K_l$).
    pub load_stiffness: Matrix<K>,
    /// Centripetal and gyroscopic terms ($C_m$).
    pub momentum: Matrix<K>,
    /// Kinematic velocity terms ($\dot p = w - V p$).
    pub velocity: Matrix<K>,
    /// Rigid constraint Jacobian $J$ (one row per carried direction: the independent rows
    /// of the carried projections).
    pub constraint: Matrix<K>,
    /// Nonholonomic constraint Jacobian $J_n$.
    pub nh_constraint: Matrix<K>,
    /// Right and left bases ($R$, $L$, columns).
    pub right_basis: Matrix<K>,
    pub left_basis: Matrix<K>,
}

/// A chain of `n` unit masses sliding along x, joined by unit springs and unit dampers,
/// the first tied to the ground; input a force on the last, output its position.
pub fn chain<K: Field>(k: &K, n: usize) -> Model<K> {
    let z = || geometry::zero3(k);
    let pt = |x: i64| [k.from_i64(x), k.zero(), k.zero()];
    let mut m = Model {
        field: k.clone(),
        name: Some(format!("{n}-body chain")),
        bodies: vec![],
        points: vec![],
        lines: vec![],
        loads: vec![],
    };
    for i in 0..n {
        m.bodies.push(Body {
            name: format!("m{}", i + 1),
            mass: k.one(),
            location: pt(2 * i as i64 + 2),
            inertia: Matrix::identity(k.clone(), 3),
            velocity: z(),
            angular_velocity: z(),
        });
        m.points.push(PointItem {
            name: format!("slider {}", i + 1),
            kind: PointKind::Rigid,
            bodies: [i, n],
            location: pt(2 * i as i64 + 2),
            forces: 2,
            moments: 3,
            axis: pt(1),
            rolling_axis: None,
            stiffness: [k.zero(), k.zero()],
            damping: [k.zero(), k.zero()],
        });
        m.lines.push(LineItem {
            name: format!("spring {}", i + 1),
            kind: LineKind::Spring {
                stiffness: k.one(),
                damping: k.one(),
            },
            bodies: [if i == 0 { n } else { i - 1 }, i],
            locations: [pt(2 * i as i64), pt(2 * i as i64 + 2)],
            twist: false,
        });
    }
    let last = 2 * n as i64;
    m.lines.push(LineItem {
        name: "f".into(),
        kind: LineKind::Actuator {
            gain: k.one(),
            rate_gain: k.zero(),
        },
        bodies: [n - 1, n],
        locations: [pt(last), pt(last - 1)],
        twist: false,
    });
    m.lines.push(LineItem {
        name: "x".into(),
        kind: LineKind::Sensor {
            gain: k.one(),
            order: 1,
            local: false,
            actuator: None,
        },
        bodies: [n - 1, n],
        locations: [pt(last), pt(last - 1)],
        twist: false,
    });
    m
}
