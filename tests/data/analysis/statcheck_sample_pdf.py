# Writes tests/data/analysis/statcheck_sample.pdf: page 1 one column of results (one typeset with
# JESP's "b" for "<"), page 2 two columns whose left column breaks a result over two lines, so that
# a reader in physical layout would interleave it with the right column. Helvetica, WinAnsi, no
# embedded font. Run: python3 statcheck_sample_pdf.py statcheck_sample.pdf
import sys

page1 = [(72, 720, "Results"), (72, 706, "The effect was significant, t(28) = 2.20, p = .04."),
         (72, 692, "Typeset as in JESP: F(1, 76) = 23.95, p b .001, and"),
         (72, 678, "an inconsistent one, t(28) = 1.20, p = .03.")]
left = ["In the second study the effect of", "transparency was large, t(40) =", "3.10, p = .004, as the first",
        "study had suggested for all the", "participants who took part in it."]
right = ["The right column talks about", "something else entirely and has", "no statistics in it at all, only",
         "words that a reader must keep", "apart from the left column."]
page2 = [(72, 720 - 14 * i, s) for i, s in enumerate(left)] + [(320, 720 - 14 * i, s) for i, s in enumerate(right)]


def stream(lines):
    ops = ["BT", "/F1 11 Tf"]
    for x, y, s in lines:
        esc = s.replace("\\", "\\\\").replace("(", "\\(").replace(")", "\\)")
        ops.append("1 0 0 1 %d %d Tm (%s) Tj" % (x, y, esc))
    ops.append("ET")
    content = "\n".join(ops) + "\n"
    return "<< /Length %d >>\nstream\n%sendstream" % (len(content), content)


page = "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 612 792] /Resources << /Font << /F1 3 0 R >> >> /Contents %d 0 R >>"
objs = ["<< /Type /Catalog /Pages 2 0 R >>",
        "<< /Type /Pages /Kids [4 0 R 6 0 R] /Count 2 >>",
        "<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>",
        page % 5, stream(page1), page % 7, stream(page2)]
out = "%PDF-1.4\n"
offsets = []
for i, o in enumerate(objs):
    offsets.append(len(out))
    out += "%d 0 obj\n%s\nendobj\n" % (i + 1, o)
xref = len(out)
out += "xref\n0 %d\n0000000000 65535 f \n" % (len(objs) + 1)
for o in offsets:
    out += "%010d 00000 n \n" % o
out += "trailer\n<< /Size %d /Root 1 0 R >>\nstartxref\n%d\n%%%%EOF\n" % (len(objs) + 1, xref)
open(sys.argv[1], "w").write(out)
