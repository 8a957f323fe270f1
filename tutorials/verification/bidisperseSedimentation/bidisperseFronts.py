#!/usr/bin/python3
# -*- coding: utf-8 -*-
"""
Exact kinematic-wave (Kynch-type) solution for batch sedimentation of a
bidisperse suspension in a closed vertical column.

Model (species i = 1 large, 2 small, equal particle density rho_p):

    d(alpha_i)/dt + d f_i(alpha_1, alpha_2)/dy = 0,        y upward, bottom y = 0

    eps     = 1 - alpha_1 - alpha_2
    V(eps)  = eps**(n+1)                                   (Richardson-Zaki factor)
    v_i     = g (rho_p - rho_f) d_i**2 / (18 mu)            (Stokes velocity)
    u_r,i   = v_i V                                         (slip, u_i - u_f = -u_r,i)
    u_f     = sum_j alpha_j u_r,j                           (zero net volume flux)
    u_i     = u_f - u_r,i
    f_i     = alpha_i u_i = alpha_i (sum_j alpha_j u_r,j - u_r,i)

Initial data: uniform mixture (alpha_1^0, alpha_2^0) in 0 < y < H, clear fluid
above, everything at rest.  A packed sediment (total fraction alpha_max, at
rest, zero flux) grows from the bottom.

Wave structure (from the top), valid for 0 <= t < t1:

    clear fluid | small-only suspension (0, a*) | mixture | bidisperse sediment

    clear_top      y = H + s_top t ,  s_top = u_2(0, a*) = -v_2 (1-a*)**(n+2)
    mixture_top    y = H + s_mix t ,  s_mix = u_1(mixture)
    sediment_top   y = s_sed t      ,  s_sed = eps0 u_f0 / (alpha_max - phi0)

For t1 <= t < t2 (mixture zone gone) a small-only sediment (0, alpha_max)
grows on top of the bidisperse one; for t >= t2 everything is settled.

API
    states(**params)     -> dict of constant states, speeds, event times, checks
    fronts(t, **params)  -> dict of front heights at time t (scalar or array)
    profiles(y, t, **params) -> (alpha_1(y), alpha_2(y)) at time t (scalar t)

Command line
    bidisperseFronts.py --time 1.0 [--alpha1 0.05 --alpha2 0.10 ...]

Only numpy is needed.
"""
import argparse
import sys

import numpy as np

DEFAULTS = dict(
    rho_p=2000.0,      # particle density [kg/m3] (both species)
    rho_f=1000.0,      # fluid density [kg/m3]
    mu=1.0e-3,         # fluid dynamic viscosity [Pa s]
    g=9.81,            # gravity [m/s2]
    d1=1.0e-3,         # diameter of species 1 (large) [m]
    d2=0.5e-3,         # diameter of species 2 (small) [m]
    alpha1=0.075,      # initial volume fraction of species 1
    alpha2=0.075,      # initial volume fraction of species 2
    H=0.8,             # initial suspension height [m]
    n=2.65,            # Richardson-Zaki exponent (V = eps**(n+1))
    alpha_max=0.6,     # packed-sediment total solids fraction
)


# ---------------------------------------------------------------------------
# basic model functions
# ---------------------------------------------------------------------------
def _params(**kw):
    unknown = set(kw) - set(DEFAULTS)
    if unknown:
        raise TypeError("unknown parameter(s): %s" % ", ".join(sorted(unknown)))
    p = dict(DEFAULTS)
    p.update({k: float(v) for k, v in kw.items()})
    if not (p["alpha1"] > 0 and p["alpha2"] > 0):
        raise ValueError("both initial fractions must be > 0")
    if not (p["alpha1"] + p["alpha2"] < p["alpha_max"] < 1):
        raise ValueError("need alpha1 + alpha2 < alpha_max < 1")
    if not p["d1"] > p["d2"]:
        raise ValueError("species 1 must be the larger one (d1 > d2)")
    if not p["rho_p"] > p["rho_f"]:
        raise ValueError("need rho_p > rho_f")
    return p


def stokes_velocities(p):
    """Single-particle Stokes settling velocities v_1, v_2 [m/s]."""
    c = p["g"] * (p["rho_p"] - p["rho_f"]) / (18.0 * p["mu"])
    return c * p["d1"] ** 2, c * p["d2"] ** 2


def velocities(a1, a2, p):
    """(eps, V, u_f, u_1, u_2) for the local state (a1, a2)."""
    v1, v2 = stokes_velocities(p)
    eps = 1.0 - a1 - a2
    V = eps ** (p["n"] + 1.0)
    uf = (a1 * v1 + a2 * v2) * V
    return eps, V, uf, uf - v1 * V, uf - v2 * V


def fluxes(a1, a2, p):
    """Species fluxes f_1, f_2 (positive upward)."""
    _, _, _, u1, u2 = velocities(a1, a2, p)
    return a1 * u1, a2 * u2


def jacobian(a1, a2, p):
    """Analytic Jacobian d f_i / d alpha_k."""
    v = np.array(stokes_velocities(p))
    a = np.array([a1, a2], dtype=float)
    n = p["n"]
    eps = 1.0 - a.sum()
    V = eps ** (n + 1.0)
    dV = -(n + 1.0) * eps ** n          # dV/dalpha_k (same for k = 1, 2)
    q = np.dot(a, v)
    J = np.empty((2, 2))
    for i in range(2):
        for k in range(2):
            J[i, k] = ((V * (q - v[i]) if i == k else 0.0)
                       + a[i] * V * v[k] + a[i] * (q - v[i]) * dV)
    return J


def eigenvalues(a1, a2, p):
    """Characteristic speeds lambda_1 <= lambda_2 of the 2x2 system."""
    lam = np.linalg.eigvals(jacobian(a1, a2, p))
    if np.max(np.abs(lam.imag)) > 1e-12:
        raise ArithmeticError("system not hyperbolic at (%g, %g)" % (a1, a2))
    return np.sort(lam.real)


def small_flux(a, p):
    """Flux of a suspension of small particles only: f(a) = -v2 a (1-a)^(n+2)."""
    v2 = stokes_velocities(p)[1]
    return -v2 * a * (1.0 - a) ** (p["n"] + 2.0)


def small_flux_prime(a, p):
    """f'(a) = -v2 (1-a)^(n+1) (1 - (n+3) a)."""
    v2 = stokes_velocities(p)[1]
    return -v2 * (1.0 - a) ** (p["n"] + 1.0) * (1.0 - (p["n"] + 3.0) * a)


def _bisect(fun, lo, hi, tol=1e-15, maxit=200):
    flo = fun(lo)
    for _ in range(maxit):
        mid = 0.5 * (lo + hi)
        fm = fun(mid)
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
        if hi - lo < tol:
            break
    return 0.5 * (lo + hi)


# ---------------------------------------------------------------------------
# constant states, speeds, events
# ---------------------------------------------------------------------------
def states(**params):
    """Constant states, front speeds, event times and admissibility checks."""
    p = _params(**params)
    v1, v2 = stokes_velocities(p)
    a10, a20, H, amax, n = p["alpha1"], p["alpha2"], p["H"], p["alpha_max"], p["n"]
    phi0 = a10 + a20

    # ---- mixture state
    eps0, V0, uf0, u10, u20 = velocities(a10, a20, p)
    f10, f20 = a10 * u10, a20 * u20
    lam_mix = eigenvalues(a10, a20, p)

    # ---- interface mixture / small-only zone: species-1 jump condition
    s_mix = f10 / a10                       # = u_1 in the mixture

    # ---- small-only concentration a*: species-2 jump condition
    #      s_mix (a - a20) = f(a) - f20
    G = lambda a: s_mix * (a - a20) - small_flux(a, p) + f20
    grid = np.linspace(1e-12, amax, 60001)
    Gg = G(grid)
    idx = np.nonzero(np.sign(Gg[:-1]) * np.sign(Gg[1:]) < 0)[0]
    roots = [_bisect(G, grid[k], grid[k + 1]) for k in idx]
    cand = []
    for a in roots:
        lam_s = eigenvalues(0.0, a, p)
        lax = (lam_s[0] < s_mix < lam_mix[0]) and (s_mix < lam_s[1])
        cand.append((a, lax))
    adm = [a for a, lax in cand if lax]
    if len(adm) != 1:
        raise ArithmeticError("no unique Lax-admissible small-only state: %r" % cand)
    a_s = adm[0]
    eps_s, V_s, uf_s, u1_s, u2_s = velocities(0.0, a_s, p)
    f2_s = a_s * u2_s
    lam_small = eigenvalues(0.0, a_s, p)
    lam_clear = eigenvalues(0.0, 0.0, p)

    # ---- top front (clear | small-only): scalar jump condition
    s_top = f2_s / a_s                      # = u_2(0, a*) = -v2 (1-a*)^(n+2)

    # ---- bidisperse sediment front
    F0 = f10 + f20                          # total solids flux = -eps0 u_f0
    s_sed = F0 / (phi0 - amax)              # = eps0 u_f0 / (amax - phi0) > 0
    a1_sed = a10 - f10 / s_sed              # = a10 (1 - u10 / s_sed)
    a2_sed = a20 - f20 / s_sed

    # ---- event 1: sediment front meets mixture_top
    t1 = H / (s_sed - s_mix)
    y1 = s_sed * t1

    # ---- regime 2: small-only sediment (0, amax) below small-only suspension
    s_sed2 = f2_s / (a_s - amax)            # = v2 a* (1-a*)^(n+2) / (amax - a*)
    # ---- event 2: top front meets the sediment
    t2 = (H - y1 + s_sed2 * t1) / (s_sed2 - s_top)
    y_final = y1 + s_sed2 * (t2 - t1)

    # ---- admissibility checks
    chk = {}
    # (a) top front, 2-shock (left = small-only below, right = clear above)
    chk["top_lax_2shock"] = bool(lam_clear[1] < s_top < lam_small[1]
                                 and lam_small[0] < s_top)
    # (b) top front, scalar Oleinik: f(a) below its chord on (0, a*)
    aa = np.linspace(0.0, a_s, 2001)[1:-1]
    chk["top_oleinik_scalar"] = bool(np.all(small_flux(aa, p) <= s_top * aa + 1e-15))
    # (c) mixture_top, 1-shock (left = mixture below, right = small-only above)
    chk["mixture_top_lax_1shock"] = bool(lam_small[0] < s_mix < lam_mix[0]
                                         and s_mix < lam_small[1])
    # (d) sediment front: all characteristics of the mixture run into it
    chk["sediment_characteristics_incoming"] = bool(lam_mix[1] < s_sed)
    chk["sediment_composition_physical"] = bool(a1_sed > 0 and a2_sed > 0)
    # (e) later small-only sediment front: scalar Kynch/Oleinik with the flux
    #     set to zero in the packed state: graph of f above the chord
    #     from (a*, f(a*)) to (amax, 0) on (a*, amax)
    bb = np.linspace(a_s, amax, 2001)[1:-1]
    chord = f2_s * (amax - bb) / (amax - a_s)
    chk["sediment2_oleinik_scalar"] = bool(np.all(small_flux(bb, p) <= chord + 1e-15))
    chk["sediment2_characteristics_incoming"] = bool(small_flux_prime(a_s, p) < s_sed2)
    chk["all_ok"] = all(chk.values())

    return dict(
        params=p,
        stokes=dict(v1=v1, v2=v2),
        mixture=dict(alpha1=a10, alpha2=a20, eps=eps0, V=V0, u_f=uf0, u1=u10,
                     u2=u20, f1=f10, f2=f20, ur1=v1 * V0, ur2=v2 * V0,
                     eigenvalues=lam_mix),
        small=dict(alpha1=0.0, alpha2=a_s, eps=eps_s, V=V_s, u_f=uf_s,
                   u1_test=u1_s, u2=u2_s, f2=f2_s, eigenvalues=lam_small,
                   all_jump_roots=[a for a, _ in cand]),
        clear=dict(alpha1=0.0, alpha2=0.0, eigenvalues=lam_clear),
        sediment=dict(alpha1=a1_sed, alpha2=a2_sed, total=a1_sed + a2_sed),
        sediment_small=dict(alpha1=0.0, alpha2=amax),
        speeds=dict(clear_top=s_top, mixture_top=s_mix, sediment_top=s_sed,
                    sediment_small_top=s_sed2),
        events=dict(t1=t1, y1=y1, t2=t2, y_final=y_final),
        checks=chk,
    )


# ---------------------------------------------------------------------------
# front positions and profiles
# ---------------------------------------------------------------------------
def fronts(t, **params):
    """Heights of all fronts at time t (scalar or array).

    'clear_top'        top of the suspension (clear fluid above)
    'mixture_top'      top of the zone containing large particles
                       (for t >= t1 this is the top of the bidisperse sediment)
    'sediment_top'     top of the packed bed (all sediment)
    'bidisperse_sediment_top'  top of the packed layer containing both species
    'regime'           1: t < t1, 2: t1 <= t < t2, 3: t >= t2
    """
    S = states(**params)
    p = S["params"]
    H = p["H"]
    sp, ev = S["speeds"], S["events"]
    t = np.asarray(t, dtype=float)
    if np.any(t < 0):
        raise ValueError("t must be >= 0")
    t1, t2, y1, yf = ev["t1"], ev["t2"], ev["y1"], ev["y_final"]
    r1, r2 = t < t1, (t >= t1) & (t < t2)

    clear_top = np.where(t < t2, H + sp["clear_top"] * t, yf)
    mixture_top = np.where(r1, H + sp["mixture_top"] * t, y1)
    sed2 = np.where(r2, y1 + sp["sediment_small_top"] * (t - t1), yf)
    sediment_top = np.where(r1, sp["sediment_top"] * t, sed2)
    bidisp = np.where(r1, sp["sediment_top"] * t, y1)
    regime = np.where(r1, 1, np.where(r2, 2, 3))

    out = dict(clear_top=clear_top, mixture_top=mixture_top,
               sediment_top=sediment_top, bidisperse_sediment_top=bidisp,
               regime=regime)
    if out["clear_top"].ndim == 0:
        out = {k: (int(v) if k == "regime" else float(v)) for k, v in out.items()}
    return out


def profiles(y, t, **params):
    """(alpha_1(y), alpha_2(y)) at time t (scalar) for heights y (array)."""
    S = states(**params)
    F = fronts(float(t), **params)
    y = np.asarray(y, dtype=float)
    a1 = np.zeros_like(y)
    a2 = np.zeros_like(y)
    mix, sml, sed = S["mixture"], S["small"], S["sediment"]
    amax = S["params"]["alpha_max"]

    # from the top down; later assignments overwrite lower zones
    m = y < F["clear_top"]
    a2[m] = sml["alpha2"]                       # small-only suspension
    if F["regime"] == 1:
        m = y < F["mixture_top"]
        a1[m], a2[m] = mix["alpha1"], mix["alpha2"]
    else:
        m = y < F["sediment_top"]               # small-only sediment
        a1[m], a2[m] = 0.0, amax
    m = y < F["bidisperse_sediment_top"]
    a1[m], a2[m] = sed["alpha1"], sed["alpha2"]
    return a1, a2


# ---------------------------------------------------------------------------
# command line
# ---------------------------------------------------------------------------
def report(t, **params):
    S = states(**params)
    F = fronts(t, **params)
    p = S["params"]
    L = []
    w = L.append
    w("Bidisperse batch settling, exact kinematic solution")
    w("parameters: " + ", ".join("%s=%g" % (k, p[k]) for k in DEFAULTS))
    w("Stokes velocities: v1 = %.6f m/s, v2 = %.6f m/s"
      % (S["stokes"]["v1"], S["stokes"]["v2"]))
    mx = S["mixture"]
    w("mixture   : alpha1=%.6f alpha2=%.6f eps=%.6f V=%.6f u_f=%+.6f u1=%+.6f u2=%+.6f"
      % (mx["alpha1"], mx["alpha2"], mx["eps"], mx["V"], mx["u_f"], mx["u1"], mx["u2"]))
    w("            eigenvalues %+.6f %+.6f m/s" % tuple(mx["eigenvalues"]))
    sm = S["small"]
    w("small-only: alpha1=0 alpha2=%.6f eps=%.6f u_f=%+.6f u2=%+.6f (large test particle %+.6f)"
      % (sm["alpha2"], sm["eps"], sm["u_f"], sm["u2"], sm["u1_test"]))
    w("            eigenvalues %+.6f %+.6f m/s" % tuple(sm["eigenvalues"]))
    w("clear     : eigenvalues %+.6f %+.6f m/s" % tuple(S["clear"]["eigenvalues"]))
    sd = S["sediment"]
    w("sediment  : alpha1=%.6f alpha2=%.6f total=%.6f (then small-only: 0, %g)"
      % (sd["alpha1"], sd["alpha2"], sd["total"], p["alpha_max"]))
    sp = S["speeds"]
    w("speeds [m/s]: clear_top %+.6f, mixture_top %+.6f, sediment_top %+.6f, "
      "small-sediment_top %+.6f" % (sp["clear_top"], sp["mixture_top"],
                                    sp["sediment_top"], sp["sediment_small_top"]))
    ev = S["events"]
    w("events: t1 = %.6f s (mixture zone vanishes at y = %.6f m); "
      "t2 = %.6f s (all settled, bed height %.6f m)"
      % (ev["t1"], ev["y1"], ev["t2"], ev["y_final"]))
    w("admissibility: " + ", ".join("%s=%s" % kv for kv in S["checks"].items()))
    w("fronts at t = %g s (regime %d):" % (t, F["regime"]))
    for k in ("clear_top", "mixture_top", "bidisperse_sediment_top", "sediment_top"):
        w("  %-24s %.6f m" % (k, F[k]))
    return "\n".join(L)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--time", "-t", type=float, default=1.0, help="time [s]")
    for k, v in DEFAULTS.items():
        ap.add_argument("--" + k, type=float, default=v, help="default %g" % v)
    a = ap.parse_args(argv)
    params = {k: getattr(a, k) for k in DEFAULTS}
    print(report(a.time, **params))


if __name__ == "__main__":
    main(sys.argv[1:])
