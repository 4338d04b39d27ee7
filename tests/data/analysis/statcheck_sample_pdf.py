# Writes a minimal one-page PDF (Helvetica, WinAnsi) whose text is the lines given.
import sys
lines = ["Results", "The effect was significant, t(28) = 2.20, p = .04.",
         "Typeset as in JESP: F(1, 76) = 23.95, p b .001, and",
         "an inconsistent one, t(28) = 1.20, p = .03."]
ops = ["BT", "/F1 11 Tf", "72 720 Td", "14 TL"]
for l in lines:
    esc = l.replace("\\", "\\\\").replace("(", "\\(").replace(")", "\\)")
    ops.append("(%s) Tj T*" % esc)
ops.append("ET")
content = "\n".join(ops) + "\n"
objs = ["<< /Type /Catalog /Pages 2 0 R >>",
        "<< /Type /Pages /Kids [3 0 R] /Count 1 >>",
        "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 612 792] /Resources << /Font << /F1 4 0 R >> >> /Contents 5 0 R >>",
        "<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>",
        "<< /Length %d >>\nstream\n%sendstream" % (len(content), content)]
out = "%PDF-1.4\n"
offs = []
for i, o in enumerate(objs):
    offs.append(len(out))
    out += "%d 0 obj\n%s\nendobj\n" % (i + 1, o)
x = len(out)
out += "xref\n0 %d\n0000000000 65535 f \n" % (len(objs) + 1)
for o in offs: out += "%010d 00000 n \n" % o
out += "trailer\n<< /Size %d /Root 1 0 R >>\nstartxref\n%d\n%%%%EOF\n" % (len(objs) + 1, x)
open(sys.argv[1], "w").write(out)
