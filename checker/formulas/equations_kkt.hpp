// The KKT system of a critical lattice, written again for the checker (NOTES.md 8.9, 11.5):
// minimise det B subject to n_i(B) = ||c_i B||_(2p) = 2 for contact triples c_1..c_m (one per
// +-pair), with unknowns x = (b_00, b_01, ..., b_22, mu_1, ..., mu_m) (B row-major) and the
// Lagrangian L = det B - sum_i mu_i (n_i - 2). Values and Jacobian are derived by hand:
//   F_(3k+j) = dL/db_kj = cof_kj(B) - sum_i mu_i c_ik g_ij,   F_(9+i) = n_i - 2,
// with v_i = c_i B, u_i = v_i / n_i and g_ij = dn/dv_j = sign(v_ij) |v_ij|^(2p-1) n_i^(1-2p)
// = sign(u_ij) |u_ij|^(2p-1), and the Hessian of the norm
//   d^2n/dv_j dv_l = (2p - 1) / n (delta_jl |u_j|^(2p-2) - g_j g_l).
// For 1/2 < p < 1 the power |u_j|^(2p-2) is unbounded where u_j may be 0: the Jacobian then
// has no enclosure, and the functions here throw UnboundedPower instead of bounding it.
#pragma once
#include <stdexcept>
#include <vector>

#include "checker/core/replay.hpp"
#include "checker/formulas/equations_audit.hpp"
#include "checker/formulas/triple.hpp"

namespace superpack_checker {

// |u|^(2p-2) over an interval u that may hold 0 while 2p - 2 may be < 0.
struct UnboundedPower : std::domain_error {
    using std::domain_error::domain_error;
};

struct KktEquations {
    std::vector<Triple> contacts;  // c_1..c_m
    Real p;                        // a point or an interval
    std::vector<Real> value(const Box& x) const;
    // (9 + m) x (9 + m); rows and columns in the order of x. Rows 0..8, columns 0..8 are the
    // Hessian of the Lagrangian in B; rows 9.. columns 0..8 the constraint Jacobian A.
    std::vector<std::vector<Real>> jacobian(const Box& x) const;
    // dF/dp at fixed x, by hand: with L_i = sum_j |u_ij|^(2p) ln|u_ij| (from sum_j |u_ij|^(2p) = 1),
    //   dn_i/dp = n_i L_i / p,   dg_ij/dp = g_ij (2 ln|u_ij| - (2p - 1) L_i / p),
    //   dF_(3k+j)/dp = -sum_i mu_i c_ik dg_ij/dp,   dF_(9+i)/dp = dn_i/dp.
    // ln|u| needs every contact coordinate certainly away from 0; else UnboundedPower (S6's
    // coordinates are, and a zero one would make the Jacobian unbounded for p < 1 anyway).
    std::vector<Real> p_derivative(const Box& x) const;
};

System kkt_system(const KktEquations& equations);

// The basis as exact linear forms in the nine symbols b_kj, with one unit equation per contact
// triple: the halved coordinates of c_i B, whose 2p-th powers sum to 1 where n_i = 2. A
// lattice vector t B is a contact by such an identity exactly when t = +-c_i (the forms of
// each column involve that column's symbols only).
FamilyForms kkt_forms(const std::vector<Triple>& contacts);
// The names of the nine symbols, in the order of x: "b00", "b01", ..., "b22".
std::vector<std::string> kkt_symbols();

}  // namespace superpack_checker
