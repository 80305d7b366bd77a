// Wide integer helpers of the frame's forward differences (rpu_ip, rpu_ip_step): a w-bit wire
// sign-extended to 128 bits, floor(v / 2^e) for a constant e of either sign, and the saturation
// of a 128-bit value to w signed bits (value and flag), as the model's fixed::truncate and
// fixed::saturate. Included inside a module; the module `undef`s RPU_SX at its end.
// A w-bit field sign-extended to 128 bits (F a plain wire name).
`define RPU_SX(F, W) {{(128-(W)){F[(W)-1]}}, F}
  // (if/else, not ?: — a conditional with an unsigned arm would make the shift logical)
  function automatic [127:0] fl(input [127:0] v, input integer e);
    reg signed [127:0] vs;
    begin
      vs = v;
      if (e >= 0) fl = vs >>> e;
      else        fl = v << (-e);
    end
  endfunction
  function automatic [127:0] sat(input [127:0] v, input integer w);
    reg signed [127:0] vs, hi, lo;
    begin
      vs = v;
      hi = (128'sd1 <<< (w - 1)) - 128'sd1;
      lo = -(128'sd1 <<< (w - 1));
      sat = vs > hi ? hi : vs < lo ? lo : vs;
    end
  endfunction
  function automatic issat(input [127:0] v, input integer w);
    reg signed [127:0] vs, hi, lo;
    begin
      vs = v;
      hi = (128'sd1 <<< (w - 1)) - 128'sd1;
      lo = -(128'sd1 <<< (w - 1));
      issat = vs > hi || vs < lo;
    end
  endfunction
