#!/usr/bin/env bash
# Times `tlab statcheck` on a generated text: N sentences (default 100 000), each with a t and an
# F result (2N results, about 81 bytes per result), seeded so every run reads the same text.
#   bash scripts/statcheck_bench.sh [N]
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-100000}
text=$(mktemp --suffix=.txt)
trap 'rm -f "$text"' EXIT
python3 - "$n" "$text" <<'PY'
import random, sys
random.seed(1)
n, path = int(sys.argv[1]), sys.argv[2]
lines = ["Participants were faster, t(%d) = %.2f, p = .%03d, and F(2, %d) = %.2f, p < .05; "
         % (random.randint(5, 90), random.random() * 4, random.randint(1, 999), random.randint(10, 90),
            random.random() * 10) for _ in range(n)]
open(path, "w").write("\n".join(lines))
PY
echo "statcheck_bench: $(wc -c <"$text") bytes"
/usr/bin/time -f "statcheck_bench: %e s wall, %M KB peak" build/bin/tlab statcheck "$text" --csv | tail -n +2 | wc -l |
  sed 's/^/statcheck_bench: results: /'
