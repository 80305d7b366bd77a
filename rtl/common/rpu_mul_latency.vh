// rpu_mul's latency for given operand widths, as a constant function: included inside every
// module that instantiates rpu_mul and must know when its product arrives (one formula for all).
// Latency = 2 (tile input and product registers) + ceil(log2(tiles)) adder-tree levels.
// (Verilator sees the function's own result variable as hiding the function when several
// modules of one hierarchy include this file: a false alarm, waived here only.)
/* verilator lint_off VARHIDDEN */
function integer rpu_mul_latency(input integer aw, input integer bw, input integer signed_,
                                 input integer chunk_a, input integer chunk_b);
  integer tiles, levels;
  begin
    tiles  = ((aw - signed_ + chunk_a - 1) / chunk_a) * ((bw - signed_ + chunk_b - 1) / chunk_b);
    levels = 0;
    while ((1 << levels) < tiles) levels = levels + 1;
    rpu_mul_latency = 2 + levels;
  end
endfunction
/* verilator lint_on VARHIDDEN */
