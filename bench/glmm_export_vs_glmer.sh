#!/usr/bin/env bash
# The logistic GLMM of a simulated Carnecky study fitted by tlab and by lme4's glmer on the same
# export (run by hand, needs R with r-cran-lme4; not a test). Usage:
#   bench/glmm_export_vs_glmer.sh TRIALS.csv [TLAB]
# TRIALS.csv is `tlab export DB --csv DIR`'s trials.csv; the test-phase rows of each task are fitted
# with correct ~ method + (1 | participant) + (1 | stimulus_sha256), and the largest relative
# differences of the estimates and standard errors are printed per task.
set -euo pipefail
trials=$1
tlab=${2:-build/bin/tlab}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for task in $(python3 -c "import csv,sys; print(' '.join(sorted({r['task_id'] for r in csv.DictReader(open(sys.argv[1])) if r['phase']=='test'})))" "$trials"); do
  python3 - "$trials" "$task" "$work/$task.csv" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["phase"] == "test" and r["task_id"] == sys.argv[2] and r["correct"] != ""]
with open(sys.argv[3], "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["participant", "method", "stimulus", "correct"])
    for r in rows:
        w.writerow([r["participant"], r["method"], r["stimulus_sha256"], r["correct"]])
PY
  "$tlab" stats mixed "$work/$task.csv" --family binomial --formula "correct ~ method + (1 | participant) + (1 | stimulus)" \
      --json > "$work/$task.json"
  Rscript - "$work/$task.csv" "$work/$task.json" "$task" <<'R'
suppressMessages({ library(lme4); library(jsonlite) })
a <- commandArgs(TRUE)
d <- read.csv(a[1]); d$method <- factor(d$method, levels = unique(d$method))
tl <- fromJSON(a[2])$fixed_effects
show <- function(label, fit) {
  cf <- summary(fit)$coefficients
  est <- max(abs(tl$estimate - cf[tl$term, "Estimate"]) / abs(cf[tl$term, "Estimate"]))
  se <- max(abs(tl$std_error - cf[tl$term, "Std. Error"]) / cf[tl$term, "Std. Error"])
  cat(sprintf("%-16s glmer %-22s max rel. diff: estimates %.2e, SEs %.2e; logLik glmer %.6f\n", a[3], label, est, se, logLik(fit)))
}
f <- correct ~ method + (1 | participant) + (1 | stimulus)
show("(defaults)", glmer(f, data = d, family = binomial))
show("(tolPwrss 1e-13)", glmer(f, data = d, family = binomial,
     control = glmerControl(optimizer = "bobyqa", optCtrl = list(rhoend = 1e-11, maxfun = 1e5), tolPwrss = 1e-13)))
cat(sprintf("%-16s tlab  logLik %.6f (%d rows)\n", a[3], fromJSON(a[2])$log_likelihood, nrow(d)))
R
done
