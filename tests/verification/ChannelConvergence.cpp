// Channel verification (docs/theory.md §6.1): L2 errors of velocity and pressure against the exact
// fully developed solution on successive refinements, and the observed orders.
//
//   ChannelConvergence --check            ctest: asserts the orders (see kExpected* below)
//   ChannelConvergence --table [--max-n N] the full convergence table (docs/verification.md)
//   ChannelConvergence --beta             errors vs the stabilization factor β
//   ChannelConvergence --cutoff           errors vs the strain-rate cutoff e0 (σ0 > 0)
//   ChannelConvergence --rate-constant    asserts convergence and accuracy for γ from 10⁻¹
//                                         to 10³ (flow rates, hence velocities, scale with γ)
//   ... --pipe                            the same for the axisymmetric pipe (pipe_axisym.xml)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "ChannelExact.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/drivers/Simulation.hpp"
#include "flowform/discretization/ShapeFunctions.hpp"

using namespace flowform;
using verification::ChannelExact;

namespace {

struct Material { double sigma0, n, gamma = 1.0; };
struct Errors { double velocity, pressure; int dofs; bool converged; double seconds; };

/// Gauss–Legendre points and weights on [0, 1].
void gauss01(int m, std::vector<double>& x, std::vector<double>& w) {
  static const double p4[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  static const double w4[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  x.resize(m); w.resize(m);
  for (int i = 0; i < m; ++i) { x[i] = 0.5 * (p4[i] + 1.0); w[i] = 0.5 * w4[i]; }
}

/// Relative L2 errors ||u_h − u|| / ||u||, ||p_h − p|| / ||p||, integrated with 4×4 Gauss
/// per cell (collapsed onto triangles): exact to machine precision for the interpolated
/// fields and accurate to far below the discretization error for the exact ones.
Errors l2Errors(const Simulation& sim, const ChannelExact& exact) {
  const Mesh& mesh = sim.problem().mesh();
  const FieldSet fields = sim.gatherFields();
  const auto& u = fields.nodal[0].values;
  const auto& p = fields.nodal[1].values;
  std::vector<double> g, gw;
  gauss01(4, g, gw);
  const int npc = nodesPerCell(mesh.cellType);
  double eu = 0, nu = 0, ep = 0, np = 0;
  for (GO c = 0; c < mesh.numCells(); ++c) {
    std::array<double, 2> xy[4];
    for (int a = 0; a < npc; ++a) xy[a] = mesh.coords[mesh.cell(c)[a]];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        double xi, eta, wref;
        if (mesh.cellType == CellType::Triangle3) {  // Duffy: (s, t) ∈ [0,1]² → (s, t(1−s))
          xi = g[i]; eta = g[j] * (1.0 - g[i]); wref = gw[i] * gw[j] * (1.0 - g[i]);
        } else {
          xi = 2.0 * g[i] - 1.0; eta = 2.0 * g[j] - 1.0; wref = 4.0 * gw[i] * gw[j];
        }
        double N[4], dxi[4], deta[4];
        referenceShape(mesh.cellType, xi, eta, N, dxi, deta);
        double x = 0, y = 0, J00 = 0, J01 = 0, J10 = 0, J11 = 0, uh = 0, vh = 0, ph = 0;
        for (int a = 0; a < npc; ++a) {
          const GO node = mesh.cell(c)[a];
          x += N[a] * xy[a][0]; y += N[a] * xy[a][1];
          J00 += dxi[a] * xy[a][0]; J01 += dxi[a] * xy[a][1];
          J10 += deta[a] * xy[a][0]; J11 += deta[a] * xy[a][1];
          uh += N[a] * u[2 * node]; vh += N[a] * u[2 * node + 1]; ph += N[a] * p[node];
        }
        double w = wref * (J00 * J11 - J01 * J10);
        if (exact.axisymmetric) {
          // pipe: x = r is the radius, the flow runs along y = z, dΩ = 2π r dr dz
          w *= 2.0 * M_PI * x;
          std::swap(x, y);
          std::swap(uh, vh);
        }
        const double ue = exact.velocity(y), pe = exact.pressure(x);
        eu += w * ((uh - ue) * (uh - ue) + vh * vh);
        nu += w * ue * ue;
        ep += w * (ph - pe) * (ph - pe);
        np += w * pe * pe;
      }
  }
  return {std::sqrt(eu / nu), std::sqrt(ep / np), 0, true, 0.0};
}

bool g_pipe = false;  ///< --pipe: the axisymmetric pipe (xml/pipe_axisym.xml) instead of the channel

Teuchos::RCP<Teuchos::ParameterList> channelCase() {
  const std::string name = g_pipe ? "pipe_axisym" : "channel";
  const std::string mesh = g_pipe ? "pipe" : "channel";
  auto params = Teuchos::getParametersFromXmlFile(std::string(FLOWFORM_SOURCE_DIR) + "/xml/" + name + ".xml");
  params->sublist("Mesh").set("File", std::string(FLOWFORM_SOURCE_DIR) + "/meshes/" + mesh + ".geo");
  return params;
}

Errors solve(const std::string& cellType, int N, Material m, double beta, double cutoff,
             const Teuchos::RCP<const Comm>& comm) {
  auto params = channelCase();
  params->sublist("Mesh").set("Element Type", cellType);
  params->sublist("Mesh").sublist("Geo Parameters").set("N", double(N));
  params->sublist("Material").set("Yield Stress", m.sigma0);
  params->sublist("Material").set("Rate Exponent", m.n);
  params->sublist("Material").set("Rate Constant", m.gamma);
  params->sublist("Material").set("Strain Rate Cutoff", cutoff);
  params->sublist("Stabilization").set("Beta", beta);
  Simulation sim(*params, FLOWFORM_SOURCE_DIR, comm);
  const auto t0 = std::chrono::steady_clock::now();
  const auto& report = sim.run();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ChannelExact exact;
  exact.axisymmetric = g_pipe;
  if (g_pipe) { exact.G = 2.0; exact.pIn = 8.0; }  // xml/pipe_axisym.xml
  exact.sigma0 = m.sigma0;
  exact.n = m.n;
  exact.gamma = m.gamma;
  Errors e = l2Errors(sim, exact);
  e.dofs = static_cast<int>(sim.problem().dofMap().ownedMap()->getGlobalNumElements());
  e.converged = report.converged;
  e.seconds = seconds;
  return e;
}

const std::vector<Material> kMaterials = {{0.0, 1.0}, {0.0, 3.0}, {0.5, 5.0}};
constexpr double kBeta = 0.1;
constexpr double kCutoff = 1e-3;

}  // namespace

int main(int argc, char* argv[]) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  setLogEnabled(false);
  std::string mode = argc > 1 ? argv[1] : "--check";
  int maxN = 32;
  for (int i = 2; i < argc; ++i) {
    if (std::string(argv[i]) == "--max-n" && i + 1 < argc) maxN = std::stoi(argv[i + 1]);
    if (std::string(argv[i]) == "--pipe") g_pipe = true;
  }

  if (mode == "--beta") {
    std::printf("%-13s %4s %8s %12s %12s\n", "element", "N", "beta", "err_u", "err_p");
    for (const char* type : {"Triangle", "Quadrilateral"})
      for (int N : {16, 32})
        for (double beta : {0.01, 0.03, 0.1, 0.3, 1.0}) {
          const Errors e = solve(type, N, {0.0, 3.0}, beta, kCutoff, comm);
          std::printf("%-13s %4d %8.3g %12.4e %12.4e\n", type, N, beta, e.velocity, e.pressure);
        }
    return 0;
  }
  if (mode == "--cutoff") {
    std::printf("%-13s %4s %8s %12s %12s %4s\n", "element", "N", "e0", "err_u", "err_p", "conv");
    for (const char* type : {"Triangle", "Quadrilateral"})
      for (double e0 : {1e-1, 1e-2, 1e-3, 1e-4})
        for (int N : {16, 64}) {
          const Errors e = solve(type, N, {0.5, 5.0}, kBeta, e0, comm);
          std::printf("%-13s %4d %8.0e %12.4e %12.4e %4d\n", type, N, e0, e.velocity, e.pressure, e.converged);
        }
    return 0;
  }

  if (mode == "--rate-constant") {
    // The solver's tolerances must not assume velocities of order 1: at γ = 10³ they are
    // of order 10³ and the residual's round-off floor ε||J|| ||x|| (2.6e-10 at N = 16) is
    // above the absolute tolerance 10⁻¹⁰ (docs/verification.md §6). Asserted as in --check:
    // converged, velocity order >= 1.8 and pressure order >= 0.9 from N = 16 to 32, errors
    // at N = 32 below 5e-2.
    bool ok = true;
    std::printf("%-13s %8s %4s %12s %12s %6s %6s %4s\n", "element", "gamma", "N", "err_u", "err_p", "ord_u", "ord_p",
                "conv");
    for (double gamma : {1e-1, 1.0, 1e3}) {
      Errors previous{0, 0, 0, true, 0};
      for (int N : {16, 32}) {
        const Errors e = solve("Quadrilateral", N, {0.5, 5.0, gamma}, kBeta, kCutoff, comm);
        const double ou = N > 16 ? std::log2(previous.velocity / e.velocity) : 0.0;
        const double op = N > 16 ? std::log2(previous.pressure / e.pressure) : 0.0;
        std::printf("%-13s %8.0e %4d %12.4e %12.4e %6.2f %6.2f %4d\n", "Quadrilateral", gamma, N, e.velocity,
                    e.pressure, ou, op, e.converged);
        if (!e.converged) ok = false;
        if (N == 32 && (ou < 1.8 || op < 0.9 || e.velocity > 5e-2 || e.pressure > 5e-2)) ok = false;
        previous = e;
      }
    }
    std::printf(ok ? "channel rate constant: PASSED\n" : "channel rate constant: FAILED\n");
    return ok ? 0 : 1;
  }

  // Convergence table; --check asserts the observed orders on the finest pair.
  // Expected (docs/verification.md): velocity L2 order 2 (P1 and Q1 interpolation error
  // O(h²)); pressure L2 order >= 1 (stabilized equal-order theory: O(h) for the pressure).
  // The asserted bounds leave 0.2 below the theory for pre-asymptotic meshes: the measured
  // orders (docs/verification.md) are within 0.1 of the finest-pair values quoted there.
  const double kExpectedVelocityOrder = 1.8, kExpectedPressureOrder = 0.9, kMaxFinestError = 5e-2;
  bool ok = true;
  std::printf("%-13s %5s %3s %4s %7s %12s %6s %12s %6s %8s\n", "element", "sigma0", "n", "N", "dofs", "err_u",
              "order", "err_p", "order", "seconds");
  for (const char* type : {"Triangle", "Quadrilateral"})
    for (const Material& m : kMaterials) {
      Errors previous{0, 0, 0, true, 0};
      for (int N = 4; N <= maxN; N *= 2) {
        const Errors e = solve(type, N, m, kBeta, kCutoff, comm);
        double ou = 0, op = 0;
        if (N > 4) {
          ou = std::log2(previous.velocity / e.velocity);
          op = std::log2(previous.pressure / e.pressure);
        }
        std::printf("%-13s %5.2f %3.0f %4d %7d %12.4e %6.2f %12.4e %6.2f %8.3f%s\n", type, m.sigma0, m.n, N, e.dofs,
                    e.velocity, ou, e.pressure, op, e.seconds, e.converged ? "" : "  NOT CONVERGED");
        if (!e.converged) ok = false;
        if (N == maxN && N > 4) {
          // For σ0 > 0 the cutoff e0 = 1e-3 bounds the attainable error (see --cutoff); up to
          // N = 64 the discretization error is still far above that floor.
          if (ou < kExpectedVelocityOrder) ok = false;
          if (op < kExpectedPressureOrder) ok = false;
          // And the errors must be small, not merely shrinking: at N >= 16 the measured
          // errors are below 2e-2 (docs/verification.md); 5e-2 allows the coarser N = 16.
          if (e.velocity > kMaxFinestError || e.pressure > kMaxFinestError) ok = false;
        }
        previous = e;
      }
    }
  std::printf(ok ? "channel convergence: PASSED\n" : "channel convergence: FAILED\n");
  return ok ? 0 : 1;
}
