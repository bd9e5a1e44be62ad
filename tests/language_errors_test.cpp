// The catalogue of bad scripts: each with its exact message and line. A designer reads
// these messages daily, so their wording is tested output; none may crash, and through
// the command line none may write an output file.
#include <gtest/gtest.h>

#include "support.hpp"

namespace knitc {
namespace {

struct BadScript {
  const char* name;
  const char* source;
  const char* message;  // exact; @LIB@ stands for knitc's patterns/lib
};

void PrintTo(const BadScript& script, std::ostream* os) { *os << script.name; }

const BadScript catalogue[] = {
    {"row_too_many_stitches",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\ncast_on(2000)\nrow \"(yo) x100000, k\"\n",
     "t.lua:3: row 1 \"(yo) x100000, k\" makes more stitches than any row can hold"},
    {"groups_too_deep",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\ncast_on(2)\n"
     "row \"((((((((((((((((((k))))))))))))))))))\"\n",
     "t.lua:3: row 1 \"((((((((((((((((((k))))))))))))))))))\": groups nested more than 16 deep"},
    {"no_yarns",
     "pattern { gauge = { stitches = 20, rows = 30 } }\ncast_on(4)\nrow \"k\"\n",
     "t.lua:1: pattern{} needs yarns, e.g. yarns = { A = { diameter = 1.0, color = \"#d9c8a9\" } }"},
    {"no_gauge",
     "pattern { yarns = { A = { diameter = 1 } } }\ncast_on(4)\nrow \"k\"\n",
     "t.lua:1: pattern{} needs a gauge, e.g. gauge = { stitches = 22, rows = 30 } (per 10 cm)"},
    {"unknown_pattern_field",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 1 } }, colour = 1, bogus = 2 }\n",
     "t.lua:1: unknown field 'bogus' in pattern{}; known fields: name, gauge, yarns, knitting, first_row, selvedge, seed"},
    {"negative_gauge",
     "pattern { gauge = { stitches = -3, rows = 30 }, yarns = { A = { diameter = 1 } } }\n",
     "t.lua:1: gauge.stitches is -3 per 10 cm; it must be more than 0 per 10 cm and at most 200 per 10 cm"},
    {"absurd_gauge",
     "pattern { gauge = { stitches = 500, rows = 30 }, yarns = { A = { diameter = 1 } } }\n",
     "t.lua:1: gauge.stitches is 500 per 10 cm; it must be more than 0 per 10 cm and at most 200 per 10 cm"},
    {"mixed_gauge",
     "pattern { gauge = { stitches = 20, loop_height = 3 }, yarns = { A = { diameter = 1 } } }\n",
     "t.lua:1: gauge mixes stitches/rows with loop_width/loop_height; give one pair or the other"},
    {"nan_rows",
     "pattern { gauge = { stitches = 20, rows = 0/0 }, yarns = { A = { diameter = 1 } } }\n",
     "t.lua:1: gauge.rows is NaN; it must be more than 0 per 10 cm and at most 300 per 10 cm"},
    {"zero_diameter",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 0 } } }\n",
     "t.lua:1: yarns.A.diameter is 0 mm; it must be more than 0 mm and at most 30 mm"},
    {"bad_colour",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 1, color = \"red\" } } }\n",
     "t.lua:1: yarns.A.color is \"red\"; give a CSS hex colour such as \"#d9c8a9\""},
    {"unknown_weight",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { weight = \"dkk\" } } }\n",
     "t.lua:1: yarns.A.weight is \"dkk\"; known weights: lace, super fine (fingering/sock), fine (sport), light (dk), medium (worsted/aran), bulky (chunky), super bulky, jumbo"},
    {"diameter_and_weight",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { weight = \"dk\", diameter = 2 } } }\n",
     "t.lua:1: yarns.A gives both diameter and weight; give one"},
    {"wpi_and_tex",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { wpi = 12, tex = 300, weight = \"dk\" } } }\n",
     "t.lua:1: yarns.A gives weight, wpi and tex; give one"},
    {"no_size",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { color = \"#ffffff\" } } }\n",
     "t.lua:1: yarns.A needs a size: a diameter in mm, a weight, wpi or tex, e.g. diameter = 1.0 or weight = \"dk\""},
    {"core_not_inside",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 1, core_diameter = 1.2 } } }\n",
     "t.lua:1: yarns.A.core_diameter is 1.2 mm, not less than the free diameter 1 mm; the core is the compact middle of the yarn"},
    {"unknown_fibre",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { tex = 300, fibre = \"yak\" } } }\n",
     "t.lua:1: yarns.A.fibre is \"yak\"; known fibres: wool, cotton, linen, silk, viscose, acrylic, polyester, nylon, mohair, "
     "alpaca, cashmere"},
    {"tex_zero",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { tex = 0 } } }\n",
     "t.lua:1: yarns.A.tex is 0 tex; it must be more than 0 tex and at most 5e+04 tex"},
    {"wpi_too_few",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { wpi = 0.5 } } }\n",
     "t.lua:1: yarns.A.wpi is 0.5 wraps per inch; it must be more than 1 wraps per inch and at most 100 wraps per inch"},
    {"yarn_too_thick",
     "pattern { gauge = { stitches = 40, rows = 50 }, yarns = { A = { weight = \"bulky\" } } }\n",
     "t.lua:1: yarn A is 2.879 mm thick but a loop is only 2.5 mm wide; a loop holds a yarn of at most 1.25 mm: use a thinner yarn or fewer stitches per 10 cm"},
    {"thinner_than_yarn",
     "pattern { gauge = { loop_width = 4, loop_height = 4.2, thickness = 0.5 }, yarns = { A = { diameter = 1 } } }\n",
     "t.lua:1: gauge.thickness is 0.5 mm, thinner than yarn A (1 mm); the fabric is at least one yarn thick"},
    {"yarn_named_like_stitch",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { P = { diameter = 1 } } }\n",
     "t.lua:1: yarn name 'P' is also a stitch; name it otherwise, e.g. P1"},
    {"unknown_knitting",
     "pattern { gauge = { stitches = 20, rows = 30 }, yarns = { A = { diameter = 1 } }, knitting = \"sideways\" }\n",
     "t.lua:1: knitting is \"sideways\"; use \"round\" or \"flat\""},
    {"pattern_twice",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\npattern { gauge = {}, yarns = {} }\n",
     "t.lua:2: pattern{} was already given at line 1; give it once"},
    {"cast_on_first",
     "cast_on(4)\n",
     "t.lua:1: cast_on comes before pattern{}; declare the pattern first"},
    {"no_pattern",
     "local x = 1\n",
     "t.lua:1: the script never calls pattern{}; start it with pattern { name = ..., gauge = ..., yarns = ... }"},
    {"left_over",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(10)\nrows(2, \"k3\")\n",
     "t.lua:3: row 1 \"k3\" repeats every 3 stitches and does not fit 10 live stitches (1 left over); make the count a multiple of 3 or end the row with fixed stitches (*...; rep from * to last 1 st, ...)"},
    {"missing",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(2)\nrow \"k3\"\n",
     "t.lua:3: row 1 \"k3\" uses 3 stitches but 2 are live (1 missing); remove 1 stitch or change the repeat"},
    {"fixed_row_short",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(24)\nrow \"k10, p12, k1\"\n",
     "t.lua:3: row 1 \"k10, p12, k1\" uses 23 stitches but 24 are live (1 left over); add 1 stitch or change the repeat"},
    {"unknown_stitch",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nrow \"k, kk\"\n",
     "t.lua:3: row 1 \"k, kk\": unknown stitch 'kk'; did you mean k?"},
    {"unknown_cable",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(8)\nrow \"C4X, k4\"\n",
     "t.lua:3: row 1 \"C4X, k4\": unknown stitch 'C4X'; did you mean C4F?"},
    {"rows_before_cast_on",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\nrows(2, \"k\")\n",
     "t.lua:2: no live stitches; call cast_on(n) first"},
    {"cast_on_fraction",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(2.5)\n",
     "t.lua:2: cast_on's stitch count must be a whole number, not 2.5"},
    {"cast_on_zero",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(0)\n",
     "t.lua:2: cast_on's stitch count is 0; it must be from 1 to 100000"},
    {"cast_on_twice",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\ncast_on(4)\n",
     "t.lua:3: cast_on was already called at line 2"},
    {"empty_pattern",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\n",
     "t.lua:2: the pattern has no courses; add some, e.g. rows(10, \"k\")"},
    {"unclosed_group",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(8)\nrow \"(k2, p2 x2\"\n",
     "t.lua:3: row 1 \"(k2, p2 x2\": '(' is never closed"},
    {"mismatched_bracket",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(8)\nrow \"(k2, p2] x2\"\n",
     "t.lua:3: row 1 \"(k2, p2] x2\": '(' is closed by ']'"},
    {"bad_group_count",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(8)\nrow \"(k2, p2) lots\"\n",
     "t.lua:3: row 1 \"(k2, p2) lots\": \"lots\" after a group is not a repeat count; write x6 or 6 times"},
    {"star_without_rep",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(8)\nrow \"*k2, p2\"\n",
     "t.lua:3: row 1 \"*k2, p2\": a *repeat needs \"; rep from *\" after it"},
    {"rep_to_last_disagrees",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(10)\nrow \"*k2, p2; rep from * to last 2 sts, k3\"\n",
     "t.lua:3: row 1 \"*k2, p2; rep from * to last 2 sts, k3\" repeats to the last 2 stitches but 3 stitches follow the repeat; make the two agree"},
    {"star_does_not_fit",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(11)\nrow \"k1, *k2, p2; rep from *\"\n",
     "t.lua:3: row 1 \"k1, *k2, p2; rep from *\": the *repeat of 4 stitches does not fit the 10 stitches between the fixed ones (2 left over); change the repeat or the fixed stitches"},
    {"bad_rep_clause",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(8)\nrow \"*k2, p2; rep from * forever\"\n",
     "t.lua:3: row 1 \"*k2, p2; rep from * forever\": \"rep from * forever\" is not understood; write \"rep from *\", \"rep from * to end\" or \"rep from * to last N sts, ...\""},
    {"cable_wider_than_fabric",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nrow \"C6F\"\n",
     "t.lua:3: row 1 \"C6F\": C6F needs 6 stitches but only 4 are live; a cable cannot be wider than the fabric"},
    {"decrease_at_edge",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(5)\nrow \"k2tog, k2tog, k2tog\"\n",
     "t.lua:3: row 1 \"k2tog, k2tog, k2tog\": k2tog at the edge has no neighbour to work with: it needs 2 stitches but 1 is left; move it in from the edge"},
    {"count_on_uncounted",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nrow \"ssk2\"\n",
     "t.lua:3: row 1 \"ssk2\": ssk takes no count ('ssk2'); repeat it with commas or a group"},
    {"undeclared_yarn_verb",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nyarn \"C\"\n",
     "t.lua:3: yarn 'C' was never declared; declare it in pattern{ yarns = ... } (declared: A, B)"},
    {"undeclared_yarn_in_text",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nrow \"k2 C, k2\"\n",
     "t.lua:3: row 1 \"k2 C, k2\": yarn 'C' in 'k2 C' was never declared; declare it in pattern{ yarns = ... }"},
    {"cast_on_undeclared_yarn",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4, \"Z\")\n",
     "t.lua:2: yarn 'Z' was never declared; declare it in pattern{ yarns = ... } (declared: A, B)"},
    {"ws_cable_flat",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2 } }, knitting = \"flat\" }\ncast_on(8)\nrow \"k\"\nrow \"1/1/1 RPC, k5\"\n",
     "t.lua:4: row 2 \"1/1/1 RPC, k5\" is a wrong-side row: 1/1/1 RPC worked from the wrong side shows purled outer stitches crossing around a knit middle on the face, which knitc cannot draw yet; work it on a right-side row"},
    {"chart_unknown_symbol",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nchart [[\n  | | . .\n  | | Q .\n]]\n",
     "t.lua:5: unknown chart symbol 'Q'; did you mean . (p)? The legend has . / D H O U V \\ ^ k p v x | and stitch names such as C4F"},
    {"chart_width",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(10)\nchart [[\n  | | . .\n]]\n",
     "t.lua:4: chart row 1 (row 1) is 4 stitches wide and does not repeat evenly across 10 live stitches (2 left over); make the live count a multiple of 4"},
    {"chart_empty",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nchart [[\n\n]]\n",
     "t.lua:3: the chart has no rows"},
    {"chart_bad_rep",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nchart { [[| .]], rep = 0 }\n",
     "t.lua:3: chart{}.rep is 0; it must be from 1 to 100000"},
    {"legend_unknown_stitch",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nlegend { [\"#\"] = \"kx\" }\n",
     "t.lua:3: legend[\"#\"] is 'kx', an unknown stitch; did you mean k?"},
    {"tucks_stacked",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nrows(5, \"tuck, k\")\n",
     "t.lua:3: row 5 stacks 5 tucks on stitch 2; a needle holds at most 4 before they cannot be knitted off: knit the stitch in between"},
    {"rows_after_bind_off",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nrow \"k\"\nbind_off()\nrow \"k\"\n",
     "t.lua:5: no live stitches: all were bound off at line 4"},
    {"bind_off_at_once",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nbind_off()\n",
     "t.lua:3: bind_off right after cast_on leaves no fabric; knit some rows first"},
    {"require_missing",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\nlocal m = require \"nope\"\n",
     "t.lua:2: module \"nope\" not found; looked for:\n\tlib/nope.lua\n\t@LIB@/nope.lua"},
    {"require_escape",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\nlocal m = require \"../../etc/passwd\"\n",
     "t.lua:2: module name \"../../etc/passwd\" must be letters, digits, _ and -, with dots between folders, e.g. \"lace.edgings\""},
    {"knitspeak_row_twice",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\ncast_on(4)\n"
     "knitspeak [[\nRow 1 (RS): Knit.\nRows 1 and 2: Purl.\n]]\n",
     "t.lua:5: row 1 is given twice"},
    {"knitspeak_gap",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\ncast_on(4)\n"
     "knitspeak [[\nRow 1: Knit.\nRow 3: Knit.\n]]\n",
     "t.lua:5: row 3 is given but row 2 never is; number the rows without a gap"},
    {"knitspeak_unknown_stitch_on_its_line",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\ncast_on(4)\n"
     "knitspeak [[\n  Round 1: Knit.\n  Round 2: k2, p2tig.\n]]\n",
     "t.lua:5: row 2 \"k2, p2tig\": unknown stitch 'p2tig'; did you mean p2tog?"},
    {"knitspeak_count_does_not_come_out",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\ncast_on(4)\n"
     "knitspeak [[\nRnd 1: k1, yo, k3 (6 sts).\n]]\n",
     "t.lua:4: row 1 of the text says it leaves 6 sts but its stitches leave 5; the text's count does not come out (check the "
     "row or the cast-on)"},
    {"knitspeak_repeat_of_rows_not_given",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\ncast_on(4)\n"
     "knitspeak [[\nRnd 1: Knit.\nRepeat rnds 1-2.\n]]\n",
     "t.lua:5: repeats row 2, which has not been given before this line"},
    {"knitspeak_side_disagrees",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\ncast_on(4)\n"
     "knitspeak [[\nRow 1 (RS): Knit.\nRow 2 (RS): Knit.\n]]\n",
     "t.lua:5: row 2 of the text is printed as a right-side row but is row 2 of the fabric, a wrong-side row; check the rows "
     "before it"},
    {"psso_alone",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\ncast_on(4)\nrow \"k2, psso, k2\"\n",
     "t.lua:3: row 1 \"k2, psso, k2\": psso passes a slipped stitch over the one just worked: write it after \"sl1, k1\" or "
     "\"sl1, k2tog\""},
    {"open_repeat_twice",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } } }\ncast_on(4)\nrow \"k to last st, p to end\"\n",
     "t.lua:3: row 1 \"k to last st, p to end\": a row can have one repeat only"},
    {"lua_runtime_error",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nlocal x = nil + 1\n",
     "t.lua:3: attempt to perform arithmetic on a nil value"},
    {"error_with_table",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nerror({})\n",
     "t.lua:3: error raised with a table value instead of a message; pass error() a string"},
    {"syntax_error",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nrow \"k\"\nfor\n",
     "t.lua:5: <name> expected near <eof>"},
    {"course_number_item",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\ncourse { k, 3 }\n",
     "t.lua:3: course{} item 2 is a number; give stitches such as k, p, k2tog or \"sl1 wyif\""},
    {"course_unknown_field",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\ncourse { k, p, times = 2 }\n",
     "t.lua:3: unknown field 'times' in course{}; known fields: rep, yarn"},
    {"course_empty",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\ncourse {}\n",
     "t.lua:3: course{} lists no stitches; give some, e.g. course { k, p }"},
    {"course_rep_mismatch",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(12)\ncourse { k, k, p, p, rep = 2 }\n",
     "t.lua:3: row 1 \"(k, k, p, p) x2\" uses 8 stitches but 12 are live (4 left over); add 4 stitches or change the repeat"},
    {"row_not_text",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nrow(5)\n",
     "t.lua:3: row takes the row's written instructions as a string, e.g. row(\"k2, p2\"), not a number"},
    {"decreased_to_nothing",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(2)\nrow \"k2tog\"\nrow \"k2tog\"\n",
     "t.lua:4: row 2 \"k2tog\": k2tog at the edge has no neighbour to work with: it needs 2 stitches but 1 is left; move it in from the edge"},
    {"undefined_verb",
     "pattern { name = \"t\", gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1.2, color = \"#aabbcc\" }, B = { weight = \"dk\" } } }\ncast_on(4)\nrows_(2, \"k\")\n",
     "t.lua:3: attempt to call a nil value (global 'rows_'); did you mean rows?"},
    // Spellings that could mean more than one stitch (issue 17): refused, candidates named.
    {"ambiguous_decrease",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\ncast_on(4)\nrow \"k1, dec, k1\"\n",
     "t.lua:3: row 1 \"k1, dec, k1\": 'dec' could mean k2tog, ssk or p2tog (a decrease, but the pattern does not say which); write the one the pattern means"},
    {"ambiguous_cable_in_legend",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\ncast_on(4)\nchart { legend = { X = \"C4\" }, \"X---\" }\n",
     "t.lua:3: chart{}.legend[\"X\"]: 'C4' could mean C4F or C4B (a cable, but not which way it crosses); write the one the pattern means"},
    {"ambiguous_make_one_in_knitspeak",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\ncast_on(4)\nknitspeak [[\nRow 1 (RS): k1, make one, k3.\n]]\n",
     "t.lua:4: row 1 \"k1, make one, k3\": 'make 1' could mean m1 or yo (a lifted increase in modern patterns, a yarn over (\"make one by bringing the wool forward\") in Victorian and early 20th-century ones); write the one the pattern means"},
    {"ambiguous_purl_b",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\ncast_on(4)\nrow \"k1, p1b, k2\"\n",
     "t.lua:3: row 1 \"k1, p1b, k2\": 'p1b' could mean p tbl or p below (purl into the back of the stitch in British patterns, purl into the stitch below in Walker's and in brioche); write the one the pattern means"},
    {"count_run_in_too_large",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\ncast_on(4)\nrow \"k2, p2000000\"\n",
     "t.lua:3: row 1 \"k2, p2000000\": the count in 'p2000000' must be from 1 to 100000"},
    {"plated_with_itself",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 }, B = { diameter = 1 } } }\ncast_on(4)\nyarn(\"A\", \"A\")\n",
     "t.lua:3: yarn(\"A\", \"A\") plates a yarn with itself; name two different yarns, or one"},
    {"plated_not_a_name",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 }, B = { diameter = 1 } } }\ncast_on(4)\nyarn(\"A\", 2)\n",
     "t.lua:3: yarn's second yarn, knitted with the first, must be a declared yarn's name, e.g. yarn(\"A\", \"B\")"},
    {"plated_undeclared",
     "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 }, B = { diameter = 1 } } }\ncast_on(4)\nyarn(\"A\", \"C\")\n",
     "t.lua:3: yarn 'C' was never declared; declare it in pattern{ yarns = ... } (declared: A, B)"},
};

std::string expected(const BadScript& script) {
  std::string m = script.message;
  const std::string lib = std::string(KNITC_SOURCE_DIR) + "/patterns/lib";
  for (auto at = m.find("@LIB@"); at != std::string::npos; at = m.find("@LIB@")) m.replace(at, 5, lib);
  return m;
}

class Catalogue : public ::testing::TestWithParam<BadScript> {};

TEST_P(Catalogue, FailsWithItsMessage) {
  const BadScript& script = GetParam();
  try {
    runtime::run_pattern(script.source, "t.lua");
    FAIL() << "no error";
  } catch (const runtime::PatternError& e) {
    EXPECT_EQ(e.what(), expected(script));
  }
}

INSTANTIATE_TEST_SUITE_P(BadScripts, Catalogue, ::testing::ValuesIn(catalogue),
                         [](const ::testing::TestParamInfo<BadScript>& p) { return std::string(p.param.name); });

TEST(CatalogueSize, HasAtLeastFortyScripts) { EXPECT_GE(std::size(catalogue), 40u); }

// Through the command line: exit 1, the message on stderr, and no file written.
TEST(CatalogueCli, ExitsOneAndWritesNothing) {
  const auto dir = test::scratch_dir("catalogue");
  for (const BadScript& script : catalogue) {
    test::write_text(dir / "t.lua", script.source);
    const auto r = test::run_knitc("build '" + (dir / "t.lua").string() + "' -o '" + (dir / "out.glb").string() + "'");
    EXPECT_EQ(r.exit_code, 1) << script.name;
    EXPECT_NE(r.err.find(":"), std::string::npos) << script.name;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.glb")) << script.name;
  }
  std::filesystem::remove_all(dir);
}

// What only the knit graph sees, a dropped stitch whose wale cannot unravel as one, is
// refused at the row that drops it by check and by build alike.
TEST(CatalogueCli, ADropThatCannotUnravelIsRefusedByCheckAndBuild) {
  const auto dir = test::scratch_dir("catalogue_drop");
  test::write_text(dir / "t.lua",
                   "pattern { gauge = { stitches = 20, rows = 28 }, yarns = { A = { diameter = 1 } }, knitting = \"flat\" }\n"
                   "cast_on(3)\nrow \"k2tog, k1\"\nrow \"p1, drop\"\n");
  const std::string message =
      "t.lua:4: row 2 drops a stitch whose wale would unravel down through 2 stitches worked together at row 1; a "
      "dropped stitch unravels to a yarn over: drop one made by a yo above that row";
  const std::string script = "'" + (dir / "t.lua").string() + "'";
  for (const std::string& command : {"check " + script, "build " + script + " -o '" + (dir / "out.glb").string() + "'"}) {
    const auto r = test::run_knitc(command);
    EXPECT_EQ(r.exit_code, 1) << command;
    EXPECT_NE(r.err.find(message), std::string::npos) << command << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.glb")) << command;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace knitc
