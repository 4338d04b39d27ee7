# Reference data sets and values for the mixed models, pairwise tests and Bayes factors of tlab
# (tests/analysis/mixed_model_test.cpp, inference_test.cpp), computed with R 4.2.2 and the Debian 12
# packages r-cran-lme4 (1.1-31), r-cran-lmertest (3.1-3), r-cran-bayesfactor (0.9.12-4.4).
# Run from the repository root:   Rscript tests/analysis/reference/mixed_models.R
# It writes tests/analysis/reference/mixed/*.csv (the data, generated here with fixed seeds) and
# tests/analysis/reference/mixed/expected.csv (model, section, name, field, value; 17 digits).
#
# The lmer/glmer fits use tightened optimizer tolerances so that the reference is the optimum itself,
# not the point where the default tolerances stop (the "default" rows record lme4's default fit).
suppressMessages({ library(lme4); library(lmerTest); library(BayesFactor) })
out <- "tests/analysis/reference/mixed"
dir.create(out, showWarnings = FALSE)
rows <- list()
put <- function(model, section, name, field, value)
  rows[[length(rows) + 1]] <<- data.frame(model = model, section = section, name = name, field = field,
                                          value = trimws(formatC(value, digits = 17, format = "g")))
ff <- function(x) factor(x, levels = unique(x))   # factor levels in file order, as tlab
tight_lmer <- lmerControl(optimizer = "nloptwrap", optCtrl = list(ftol_abs = 1e-15, xtol_abs = 1e-12, ftol_rel = 1e-15, xtol_rel = 1e-12, maxeval = 1e5))
# tolPwrss: PIRLS to full precision, so that the deviance is the Laplace approximation itself (with
# the default 1e-7 its last weights lag the mode and the deviance moves by ~1e-3).
tight_glmer <- glmerControl(optimizer = "bobyqa", optCtrl = list(rhoend = 1e-11, maxfun = 1e5), tolPwrss = 1e-13)

record <- function(model, fit, formula) {
  cf <- summary(fit)$coefficients
  for (i in seq_len(nrow(cf))) {
    put(model, "fixed", rownames(cf)[i], "estimate", cf[i, "Estimate"])
    put(model, "fixed", rownames(cf)[i], "std_error", cf[i, "Std. Error"])
    if ("df" %in% colnames(cf)) put(model, "fixed", rownames(cf)[i], "df", cf[i, "df"])
    put(model, "fixed", rownames(cf)[i], "p", cf[i, ncol(cf)])
  }
  vc <- as.data.frame(VarCorr(fit))
  for (i in seq_len(nrow(vc))) {
    name <- paste(vc$grp[i], ifelse(is.na(vc$var1[i]), "", vc$var1[i]), ifelse(is.na(vc$var2[i]), "", vc$var2[i]), sep = "|")
    put(model, "random", name, "variance", vc$vcov[i])
    put(model, "random", name, "sd_cor", vc$sdcor[i])
  }
  put(model, "fit", "", "log_likelihood", as.numeric(logLik(fit)))
  put(model, "fit", "", "aic", AIC(fit))
  if (isREML(fit)) put(model, "fit", "", "reml_criterion", REMLcrit(fit))
  put(model, "fit", "", "singular", as.numeric(isSingular(fit)))
  cat(model, ":", formula, "\n"); print(summary(fit)$coefficients)
}
record_default <- function(model, fit) {
  cf <- summary(fit)$coefficients
  for (i in seq_len(nrow(cf))) {
    put(model, "default", rownames(cf)[i], "estimate", cf[i, "Estimate"])
    put(model, "default", rownames(cf)[i], "std_error", cf[i, "Std. Error"])
  }
}
fit_lmm <- function(model, data, formula, REML = TRUE) {
  f <- as.formula(formula)
  record(model, lmerTest::lmer(f, data = data, REML = REML, control = tight_lmer), formula)
  record_default(model, lme4::lmer(f, data = data, REML = REML))
}
fit_glmm <- function(model, data, formula) {
  f <- as.formula(formula)
  record(model, glmer(f, data = data, family = binomial, control = tight_glmer), formula)
  record_default(model, glmer(f, data = data, family = binomial))
}

# 1. Crossed random intercepts, balanced: 24 participants x 30 stimuli, a 3-level within factor.
set.seed(31)
d1 <- expand.grid(stimulus = sprintf("s%02d", 1:30), participant = sprintf("p%02d", 1:24), stringsAsFactors = FALSE)[, 2:1]
d1$method <- c("alpha", "smart", "halo")[(match(d1$stimulus, unique(d1$stimulus)) + match(d1$participant, unique(d1$participant))) %% 3 + 1]
pe <- rnorm(24, 0, 0.25); se <- rnorm(30, 0, 0.15)
d1$rt <- round(exp(0.2 + c(alpha = 0, smart = -0.12, halo = 0.05)[d1$method] + pe[match(d1$participant, unique(d1$participant))] +
                     se[match(d1$stimulus, unique(d1$stimulus))] + rnorm(nrow(d1), 0, 0.3)), 4)
write.csv(d1, file.path(out, "crossed.csv"), row.names = FALSE, quote = FALSE)
d1f <- within(d1, { method <- ff(method); participant <- ff(participant); stimulus <- ff(stimulus) })
fit_lmm("crossed", d1f, "log(rt) ~ method + (1 | participant) + (1 | stimulus)")
fit_lmm("crossed_ml", d1f, "log(rt) ~ method + (1 | participant) + (1 | stimulus)", REML = FALSE)

# 2. Correlated random slopes: 2x2 within design, (1 + method | participant) + (1 | stimulus).
set.seed(32)
d2 <- expand.grid(rep = 1:2, stimulus = sprintf("img%02d", 1:16), participant = sprintf("p%02d", 1:20), stringsAsFactors = FALSE)[, 3:1]
d2$method <- ifelse((match(d2$stimulus, unique(d2$stimulus)) + d2$rep) %% 2 == 0, "plain", "smart")
d2$alpha <- ifelse(match(d2$stimulus, unique(d2$stimulus)) <= 8, "0.3", "0.6")
b0 <- rnorm(20, 0, 40); b1 <- 0.6 * b0 / 40 * 25 + rnorm(20, 0, 20); s0 <- rnorm(16, 0, 30)
ip <- match(d2$participant, unique(d2$participant)); is <- match(d2$stimulus, unique(d2$stimulus))
d2$time <- round(600 + b0[ip] + (d2$method == "smart") * (-45 + b1[ip]) + (d2$alpha == "0.6") * 30 +
                   (d2$method == "smart") * (d2$alpha == "0.6") * 20 + s0[is] + rnorm(nrow(d2), 0, 60), 3)
d2$rep <- NULL
write.csv(d2, file.path(out, "slopes.csv"), row.names = FALSE, quote = FALSE)
d2f <- within(d2, { method <- ff(method); alpha <- ff(alpha); participant <- ff(participant); stimulus <- ff(stimulus) })
fit_lmm("slopes", d2f, "time ~ method * alpha + (1 + method | participant) + (1 | stimulus)")

# 3. Unbalanced with missing cells: 18 participants x 24 items, 30 % of the trials missing and
#    some participants never see one of the conditions; a numeric covariate.
set.seed(33)
d3 <- expand.grid(item = sprintf("i%02d", 1:24), participant = sprintf("s%02d", 1:18), stringsAsFactors = FALSE)[, 2:1]
d3$condition <- c("A", "B", "C")[(match(d3$item, unique(d3$item)) %% 3) + 1]
ip <- match(d3$participant, unique(d3$participant)); ii <- match(d3$item, unique(d3$item))
d3$trial <- ii
d3$score <- round(10 + c(A = 0, B = 1.5, C = -0.8)[d3$condition] + 0.05 * d3$trial + rnorm(18, 0, 1.5)[ip] + rnorm(24, 0, 1)[ii] +
                    rnorm(nrow(d3), 0, 2), 3)
keep <- runif(nrow(d3)) > 0.3 & !(d3$participant %in% c("s03", "s07", "s11") & d3$condition == "C") &
        !(d3$participant == "s15" & d3$condition == "B")
d3 <- d3[keep, ]
write.csv(d3, file.path(out, "unbalanced.csv"), row.names = FALSE, quote = FALSE)
d3f <- within(d3, { condition <- ff(condition); participant <- ff(participant); item <- ff(item) })
fit_lmm("unbalanced", d3f, "score ~ condition + trial + (1 | participant) + (1 | item)")

# 4. Nested grouping: classes within schools, plus crossed raters.
set.seed(34)
d4 <- expand.grid(pupil = 1:6, class = c("a", "b", "c"), school = sprintf("sch%d", 1:8), stringsAsFactors = FALSE)[, 3:1]
d4$rater <- sprintf("r%d", (seq_len(nrow(d4)) %% 5) + 1)
d4$treatment <- ifelse(d4$pupil <= 3, "control", "training")
sc <- rnorm(8, 0, 2); cl <- rnorm(24, 0, 1); ra <- rnorm(5, 0, 0.7)
d4$grade <- round(50 + 2 * (d4$treatment == "training") + sc[match(d4$school, unique(d4$school))] +
                    cl[(match(d4$school, unique(d4$school)) - 1) * 3 + match(d4$class, c("a", "b", "c"))] +
                    ra[match(d4$rater, unique(d4$rater))] + rnorm(nrow(d4), 0, 1.5), 2)
d4$pupil <- NULL
write.csv(d4, file.path(out, "nested.csv"), row.names = FALSE, quote = FALSE)
d4f <- within(d4, { treatment <- ff(treatment); school <- ff(school); class <- ff(class); rater <- ff(rater) })
fit_lmm("nested", d4f, "grade ~ treatment + (1 | school/class) + (1 | rater)")

# 5. Logistic GLMM, crossed intercepts: 30 participants x 40 stimuli, 3 methods.
set.seed(35)
d5 <- expand.grid(stimulus = sprintf("h%02d", 1:40), participant = sprintf("p%02d", 1:30), stringsAsFactors = FALSE)[, 2:1]
ip <- match(d5$participant, unique(d5$participant)); is <- match(d5$stimulus, unique(d5$stimulus))
d5$method <- c("alpha", "smart", "halo")[(ip + is) %% 3 + 1]
eta <- 0.8 + c(alpha = 0, smart = 0.6, halo = -0.3)[d5$method] + rnorm(30, 0, 0.7)[ip] + rnorm(40, 0, 0.5)[is]
d5$correct <- rbinom(nrow(d5), 1, plogis(eta))
write.csv(d5, file.path(out, "binary_crossed.csv"), row.names = FALSE, quote = FALSE)
d5f <- within(d5, { method <- ff(method); participant <- ff(participant); stimulus <- ff(stimulus) })
fit_glmm("binary_crossed", d5f, "correct ~ method + (1 | participant) + (1 | stimulus)")

# 6. Logistic GLMM with a correlated random slope and a missing-cell, unbalanced design.
set.seed(36)
d6 <- expand.grid(stimulus = sprintf("h%02d", 1:24), participant = sprintf("p%02d", 1:40), stringsAsFactors = FALSE)[, 2:1]
ip <- match(d6$participant, unique(d6$participant)); is <- match(d6$stimulus, unique(d6$stimulus))
d6$layers <- ifelse(is %% 2 == 0, "two", "four")
u0 <- rnorm(40, 0, 0.8); u1 <- 0.5 * u0 + rnorm(40, 0, 0.5)
eta <- 1.2 - 0.9 * (d6$layers == "four") + u0[ip] + u1[ip] * (d6$layers == "four") + rnorm(24, 0, 0.4)[is]
d6$correct <- rbinom(nrow(d6), 1, plogis(eta))
d6 <- d6[runif(nrow(d6)) > 0.2, ]
write.csv(d6, file.path(out, "binary_slopes.csv"), row.names = FALSE, quote = FALSE)
d6f <- within(d6, { layers <- ff(layers); participant <- ff(participant); stimulus <- ff(stimulus) })
fit_glmm("binary_slopes", d6f, "correct ~ layers + (1 + layers | participant) + (1 | stimulus)")

# 7. Pairwise t-tests (pairwise.t.test + p.adjust) on the crossed data: per participant means.
m1 <- aggregate(rt ~ participant + method, data = d1f, FUN = mean)
m1 <- m1[order(m1$participant, m1$method), ]
for (adj in c("holm", "bonferroni", "BH", "hochberg", "none")) {
  pw <- pairwise.t.test(m1$rt, m1$method, paired = TRUE, p.adjust.method = adj)
  pr <- pairwise.t.test(m1$rt, m1$method, paired = TRUE, p.adjust.method = "none")
  for (i in rownames(pw$p.value)) for (j in colnames(pw$p.value)) if (!is.na(pw$p.value[i, j])) {
    put("pairwise_within", adj, paste(j, i, sep = "|"), "p", pr$p.value[i, j])
    put("pairwise_within", adj, paste(j, i, sep = "|"), "p_adjusted", pw$p.value[i, j])
  }
}
for (adj in c("holm", "bonferroni", "BH", "hochberg", "none")) {   # between: PlantGrowth, pooled SD
  pw <- pairwise.t.test(PlantGrowth$weight, PlantGrowth$group, p.adjust.method = adj)
  pr <- pairwise.t.test(PlantGrowth$weight, PlantGrowth$group, p.adjust.method = "none")
  for (i in rownames(pw$p.value)) for (j in colnames(pw$p.value)) if (!is.na(pw$p.value[i, j])) {
    put("pairwise_between", adj, paste(j, i, sep = "|"), "p", pr$p.value[i, j])
    put("pairwise_between", adj, paste(j, i, sep = "|"), "p_adjusted", pw$p.value[i, j])
  }
}
pw <- pairwise.t.test(PlantGrowth$weight, PlantGrowth$group, p.adjust.method = "holm", pool.sd = FALSE)
for (i in rownames(pw$p.value)) for (j in colnames(pw$p.value)) if (!is.na(pw$p.value[i, j]))
  put("pairwise_between_welch", "holm", paste(j, i, sep = "|"), "p_adjusted", pw$p.value[i, j])
p <- c(0.01, 0.04, 0.03, 0.005, 0.2, 0.04, NA)   # p.adjust with ties and a missing value
for (adj in c("holm", "bonferroni", "BH", "BY", "hochberg"))
  for (k in which(!is.na(p))) put("p_adjust", adj, as.character(k), "p_adjusted", p.adjust(p, adj)[k])

# 8. JZS Bayes factors (ttestBF, rscale "medium" and 1) on R's sleep data.
x <- sleep$extra[sleep$group == 1]; y <- sleep$extra[sleep$group == 2]
bf <- function(b) exp(b@bayesFactor$bf)
put("bayes", "paired", "medium", "bf10", bf(ttestBF(x, y, paired = TRUE)))
put("bayes", "paired", "wide", "bf10", bf(ttestBF(x, y, paired = TRUE, rscale = 1)))
put("bayes", "one_sample", "medium", "bf10", bf(ttestBF(x, mu = 0.5)))
put("bayes", "two_sample", "medium", "bf10", bf(ttestBF(x, y)))
put("bayes", "two_sample", "ultrawide", "bf10", bf(ttestBF(x, y, rscale = sqrt(2))))
put("bayes", "plant_growth", "medium", "bf10",
    bf(ttestBF(PlantGrowth$weight[PlantGrowth$group == "trt1"], PlantGrowth$weight[PlantGrowth$group == "trt2"])))

write.csv(do.call(rbind, rows), file.path(out, "expected.csv"), row.names = FALSE, quote = TRUE)
cat("wrote", length(rows), "reference values\n")
