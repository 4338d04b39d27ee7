#!/usr/bin/env python3
"""Writes a long-format CSV for timing `tlab stats mixed` by hand (bench, never a test):
P participants x S stimuli, fully crossed, a 2-level method, log-normal rt and a 0/1 correct.

    python3 bench/mixed_model_data.py 100 100 > /tmp/trials10000.csv
    /usr/bin/time -f '%e s %M KiB' build/bin/tlab stats mixed /tmp/trials10000.csv \\
        --formula "log(rt) ~ method + (1 | participant) + (1 | stimulus)" --json > /dev/null
    /usr/bin/time -f '%e s %M KiB' build/bin/tlab stats mixed /tmp/trials10000.csv --family binomial \\
        --formula "correct ~ method + (1 | participant) + (1 | stimulus)" --json > /dev/null
"""
import math
import random
import sys

participants = int(sys.argv[1]) if len(sys.argv) > 1 else 100
stimuli = int(sys.argv[2]) if len(sys.argv) > 2 else 100
rng = random.Random(31)
pe = [rng.gauss(0, 0.3) for _ in range(participants)]
se = [rng.gauss(0, 0.2) for _ in range(stimuli)]
print("participant,stimulus,method,rt,correct")
for p in range(participants):
    for s in range(stimuli):
        smart = (p + s) % 2 == 0
        eta = pe[p] + se[s] + (-0.1 if smart else 0.0)
        rt = math.exp(1.5 + eta + rng.gauss(0, 0.3))
        correct = 1 if rng.random() < 1 / (1 + math.exp(-(0.8 - 2 * eta))) else 0
        print(f"p{p:03d},s{s:03d},{'smart' if smart else 'alpha'},{rt:.4f},{correct}")
