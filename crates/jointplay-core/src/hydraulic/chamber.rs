//! Pressure in one hydraulic chamber: a constant effective bulk modulus,
//! no leakage, isothermal, no line dynamics.
//!
//! Mass continuity of a liquid with `dp = β dρ/ρ`, in a chamber of volume V
//! [m³] fed by the volume flow Q [m³/s]:
//!
//! ```text
//! dp/dt = β / V (Q - dV/dt)
//! ```
//!
//! Closed (Q = 0): `dp = -β dV/V`, so `p = p0 - β ln(V/V0)`. The work done
//! on the liquid from (p0, V0) to V, `E = -∫ p dV`, is
//!
//! ```text
//! E(V) = -p0 (V - V0) + β (V ln(V/V0) - V + V0)
//! ```
//!
//! (from `∫ ln(V'/V0) dV' = V' ln(V'/V0) - V'`). Written with the present
//! state (p, V) and `x = (p - p0)/β`, so that the same liquid would fill
//! `V0 = V e^x` at p0: `E = V ((β + p0)(e^x - 1) - β x)`, which tends to the
//! familiar `V p²/(2β)` for p0 = 0 and small x.
//! Source: H. E. Merritt, *Hydraulic Control Systems*, Wiley (1967): the
//! continuity equation of a chamber with the effective bulk modulus.
//! Theory page: `docs/theory/hydraulic-cylinder.md`.

/// Pressure rate dp/dt = β/V (Q - dV/dt) [Pa/s] for the effective bulk modulus
/// β [Pa], the volume V > 0 [m³], the inflow Q [m³/s] (into the chamber) and
/// the volume rate dV/dt [m³/s].
pub fn pressure_rate(bulk_modulus: f64, volume: f64, inflow: f64, volume_rate: f64) -> f64 {
    bulk_modulus / volume * (inflow - volume_rate)
}

/// Pressure p = p0 - β ln(V/V0) [Pa] of a closed chamber brought from
/// (p0 [Pa], V0 [m³]) to the volume V [m³]; β [Pa].
pub fn closed_pressure(initial_pressure: f64, initial_volume: f64, volume: f64, bulk_modulus: f64) -> f64 {
    initial_pressure - bulk_modulus * (volume / initial_volume).ln()
}

/// Work done on the liquid of a closed chamber, `-∫ p dV` from (p0 [Pa],
/// V0 [m³]) to V [m³], [J]: `-p0 (V - V0) + β (V ln(V/V0) - V + V0)`; β [Pa].
pub fn closed_energy(initial_pressure: f64, initial_volume: f64, volume: f64, bulk_modulus: f64) -> f64 {
    let ratio = volume / initial_volume;
    -initial_pressure * (volume - initial_volume) + bulk_modulus * (volume * ratio.ln() - volume + initial_volume)
}

/// Energy [J] stored in the liquid now at pressure p [Pa] in the volume V
/// [m³], relative to the same liquid at the reference pressure p_ref [Pa]:
/// `V ((β + p_ref)(e^x - 1) - β x)`, `x = (p - p_ref)/β`; β [Pa]. Equals
/// [`closed_energy`] along a closed compression, and its rate is `-p dV/dt`
/// when Q = 0.
pub fn compression_energy(pressure: f64, volume: f64, reference_pressure: f64, bulk_modulus: f64) -> f64 {
    let x = (pressure - reference_pressure) / bulk_modulus;
    // (β + p_ref)(e^x - 1) - β x = β (e^x - 1 - x) + p_ref (e^x - 1), without cancellation
    volume * (bulk_modulus * exp_m1_minus_x(x) + reference_pressure * x.exp_m1())
}

/// e^x - 1 - x [-], by its series where subtracting would lose digits.
fn exp_m1_minus_x(x: f64) -> f64 {
    if x.abs() < 1e-2 {
        // terms to x^6: the first omitted, x^7/5040, is < 1e-13 of x²/2
        x * x * (0.5 + x * (1.0 / 6.0 + x * (1.0 / 24.0 + x * (1.0 / 120.0 + x / 720.0))))
    } else {
        x.exp_m1() - x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BETA: f64 = 1.0e9;

    #[test]
    fn test_pressure_rate_matches_closed_form() {
        // β/V (Q - dV/dt) = 1e9 / 1e-3 * (2e-5 - 5e-6) = 1.5e7 Pa/s
        assert!((pressure_rate(BETA, 1e-3, 2e-5, 5e-6) - 1.5e7).abs() < 1e-6);
        // compression at no inflow raises the pressure
        assert!(pressure_rate(BETA, 1e-3, 0.0, -1e-6) > 0.0);
        assert_eq!(pressure_rate(BETA, 1e-3, 1e-6, 1e-6), 0.0);
    }

    #[test]
    fn test_closed_pressure_solves_the_rate_equation() {
        // integrate dp/dt for V(t) = V0 (1 - 0.3 sin t) by RK4 and compare with p0 - β ln(V/V0)
        let (p0, v0) = (2.0e6, 1.2e-3);
        let volume = |t: f64| v0 * (1.0 - 0.3 * t.sin());
        let rate = |t: f64, _p: f64| pressure_rate(BETA, volume(t), 0.0, -0.3 * v0 * t.cos());
        let (mut p, h) = (p0, 1e-3);
        for k in 0..3000 {
            let t = k as f64 * h;
            let k1 = rate(t, p);
            let k2 = rate(t + 0.5 * h, p + 0.5 * h * k1);
            let k3 = rate(t + 0.5 * h, p + 0.5 * h * k2);
            let k4 = rate(t + h, p + h * k3);
            p += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        let exact = closed_pressure(p0, v0, volume(3.0), BETA);
        // pressures of order 1e8 Pa; RK4 at h = 1e-3 s is good to ~1e-10
        assert!((p - exact).abs() < 1e-8 * exact.abs(), "{p} vs {exact}");
    }

    #[test]
    fn test_closed_energy_is_the_work_of_the_pressure() {
        // -∫ p dV by composite Simpson along p = p0 - β ln(V/V0), compression and expansion
        let (p0, v0) = (3.0e6, 1.0e-3);
        for v1 in [0.9e-3, 0.99e-3, 1.05e-3] {
            let n = 2000;
            let dv = (v1 - v0) / n as f64;
            let p = |k: usize| closed_pressure(p0, v0, v0 + k as f64 * dv, BETA);
            let mut sum = p(0) + p(n);
            for k in 1..n {
                sum += if k % 2 == 1 { 4.0 * p(k) } else { 2.0 * p(k) };
            }
            let work = -sum * dv / 3.0;
            let energy = closed_energy(p0, v0, v1, BETA);
            assert!((energy - work).abs() < 1e-9 * energy.abs(), "V = {v1}: {energy} vs {work}");
        }
    }

    #[test]
    fn test_compression_energy_agrees_with_the_closed_form_and_its_small_limit() {
        let (p0, v0) = (1.0e6, 2.0e-3);
        for v in [1.8e-3, 1.999e-3, 2.0e-3, 2.1e-3] {
            let p = closed_pressure(p0, v0, v, BETA);
            let (a, b) = (compression_energy(p, v, p0, BETA), closed_energy(p0, v0, v, BETA));
            assert!((a - b).abs() < 1e-9 * a.abs().max(1e-3), "V = {v}: {a} vs {b}");
        }
        // p_ref = 0, x = p/β small: V p²/(2β) (1 + x/3 + x²/12 + ...): 1e-3 m³ at 10 MPa holds 50.167 J
        let (e, x) = (compression_energy(1.0e7, 1.0e-3, 0.0, BETA), 0.01);
        assert!((e - 50.0 * (1.0 + x / 3.0 + x * x / 12.0)).abs() < 1e-5, "{e}");
        // and the series branch joins the exp_m1 branch continuously at |x| = 1e-2
        let (below, above) = (exp_m1_minus_x(0.01 * (1.0 - 1e-13)), exp_m1_minus_x(0.01 * (1.0 + 1e-13)));
        assert!((below - above).abs() < 1e-11 * below, "{below} vs {above}");
    }
}
