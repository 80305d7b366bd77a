// Latencies of the surface IP's parts as constant functions, included (after rpu_mul_latency.vh)
// inside rpu_surface_ip_step, rpu_surface_ip and rpu_surface_top, which need them at elaboration:
// the iterative IP's ring period and the top's admission both are one pass's latency.
// rpu_surface_indicator_latency mirrors rtl/surface/rpu_indicator.v's schedule (its localparams LF, LB,
// LatencyOwn and rpu_cordic's Latency) and ref::indicator_latency; rpu_surface_ip_step checks it
// against the instance in simulation (the lane-0 indicator's valid_o must come exactly that many
// cycles after its valid_i), so a change of the indicator's schedule stops the first simulation.
// The C++ side of every formula: ref/model/surface/rpu_surface_latency.cpp.
function integer rpu_surface_max(input integer a, input integer b);
  rpu_surface_max = a > b ? a : b;
endfunction

// rpu_indicator (SurfW = lw, AngleW = aw): 1 + LF + Tv + LT + 3 + Tr + LB.
function integer rpu_surface_indicator_latency(input integer lw, input integer aw);
  integer kf, mw, turn_w, cw, xsw, opw, psw, hiw, kw, k2w, d2w;
  integer lf, lsc, lq, lxy, lk, lkd, ln, tkd, last, cg, tv, tr;
  begin
    kf = lw; mw = lw + 2; turn_w = lw + 8; cw = lw + 6;
    xsw = lw + 3; opw = lw + 1; psw = aw + 2; hiw = turn_w + 7;
    kw = cw + 2; k2w = 2 * kw - 2 - kf; d2w = 2 * lw + 1;
    lf  = rpu_surface_max(`RPU_MUL_LATENCY(lw, kf + 2, 1, 24, 17),
                          `RPU_MUL_LATENCY(opw, mw, 1, 24, 17));
    lsc = `RPU_MUL_LATENCY(cw, kf + 2, 1, 24, 17);
    lq  = `RPU_MUL_LATENCY(lw + 1, lw + 1, 1, 24, 17);
    lxy = rpu_surface_max(`RPU_MUL_LATENCY(xsw, xsw, 1, 24, 17), 1 + lq);
    lk  = `RPU_MUL_LATENCY(kw, kw, 1, 24, 17);
    lkd = `RPU_MUL_LATENCY(k2w, d2w, 0, 24, 17);
    ln  = `RPU_MUL_LATENCY(lw, hiw, 0, 24, 17);
    tkd = rpu_surface_max(1 + lk, lxy + 1);
    last = rpu_surface_max(rpu_surface_max(lsc + lq + 3, lxy + 2),
                           rpu_surface_max(rpu_surface_max(ln + 5, 2), tkd + lkd));
    // rpu_cordic at W = cw, Iters = aw: guard bits clog2(aw) + 2, gain fraction bits W + 2.
    cg = $clog2(aw) + 2;
    tv = 1 + aw + `RPU_MUL_LATENCY(cw + cg, cw + 2, 0, 13, 17) + 1;
    tr = 1 + aw + `RPU_MUL_LATENCY(cw + 1 + cg, cw + 3, 1, 13, 17) + 1;
    rpu_surface_indicator_latency =
        1 + lf + tv + `RPU_MUL_LATENCY(psw, turn_w, 1, 24, 17) + 3 + tr + last + 1;
  end
endfunction

// One pass of rpu_surface_ip_step: products lAB'·m, the sum, the indicator, change bits, select.
function integer rpu_surface_pass_latency(input integer lw, input integer aw, input integer n);
  rpu_surface_pass_latency =
      `RPU_MUL_LATENCY(lw + 1, n + 2, 1, 24, 17) + 1 + rpu_surface_indicator_latency(lw, aw) + 2;
endfunction

// The search's schedule (ref::HwParams::surface_step_bits, docs/surfaces.md "The search on a
// piece"): step 1 takes n1f bits (0: n1, the seed's search; at most n), each later step n1 and the
// last what remains of n.
function integer rpu_surface_first_bits(input integer n, input integer n1, input integer n1f);
  rpu_surface_first_bits = n1f == 0 ? n1 : n1f < n ? n1f : n;
endfunction

// Indicators of one pass unit (ref::surface_ip_lanes): ind, or 2^n1 − 1 when ind = 0.
function integer rpu_surface_lanes(input integer n1, input integer ind);
  rpu_surface_lanes = ind != 0 ? ind : (1 << n1) - 1;
endfunction

// Passes of one item (ref::surface_ip_passes): step 1 evaluates its 2^b + 1 candidates, the ends
// among them, each later step its 2^b − 1 new ones, lanes candidates per pass.
function integer rpu_surface_passes(input integer n, input integer n1, input integer n1f,
                                    input integer ind);
  integer lanes, left, b, passes;
  begin
    lanes = rpu_surface_lanes(n1, ind);
    b = rpu_surface_first_bits(n, n1, n1f);
    left = n - b;
    passes = ((1 << b) + 1 + lanes - 1) / lanes;
    while (left > 0) begin
      b = left < n1 ? left : n1;
      left = left - b;
      passes = passes + ((1 << b) - 1 + lanes - 1) / lanes;
    end
    rpu_surface_passes = passes;
  end
endfunction
