-- Two knit columns that travel apart and back over a purled background: 2/1 RPC and
-- 2/1 LPC, the purl crosses of Stitch Maps: diamonds on reverse stockinette.
pattern {
  name = "travelling cable",
  gauge = { stitches = 24, rows = 30 },
  yarns = { A = { diameter = 1.0, color = "#b5651d" } },
  knitting = "flat",
}
cast_on(12)
for _ = 1, 3 do
  knitspeak [[
    Row 1 (RS): P3, 2/1 RPC, 2/1 LPC, p3.
    Row 2: K3, p2, k2, p2, k3.
    Row 3: P2, 2/1 RPC, p2, 2/1 LPC, p2.
    Row 4: K2, p2, k4, p2, k2.
    Row 5: P2, 2/1 LPC, p2, 2/1 RPC, p2.
    Row 6: Knit the knit sts and purl the purl sts.
    Row 7: P3, 2/1 LPC, 2/1 RPC, p3.
    Row 8: K4, p4, k4.
  ]]
end
