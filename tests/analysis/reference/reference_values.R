# Reference values for tests/analysis/*_test.cpp, computed with R 4.2.2 (Debian 12 r-base-core)
# and car 3.1 (r-cran-car). Run:  Rscript tests/analysis/reference/reference_values.R
# Every number is printed with 15 significant digits; the tests compare to >= 9 digits.
options(digits = 15)
suppressMessages(library(car))
p <- function(label, x) cat(sprintf("%-40s %s\n", label, paste(format(x, digits = 15), collapse = " ")))

cat("== sleep (R datasets) ==\n")
x <- sleep$extra[sleep$group == 1]; y <- sleep$extra[sleep$group == 2]
tp <- t.test(x, y, paired = TRUE)
p("paired t, df, p", c(tp$statistic, tp$parameter, tp$p.value)); p("paired CI", tp$conf.int)
tw <- t.test(extra ~ group, data = sleep)
p("welch t, df, p", c(tw$statistic, tw$parameter, tw$p.value)); p("welch CI", tw$conf.int)
ts <- t.test(extra ~ group, data = sleep, var.equal = TRUE)
p("student t, df, p", c(ts$statistic, ts$parameter, ts$p.value)); p("student CI", ts$conf.int)
tl <- t.test(x, y, paired = TRUE, alternative = "less")
p("paired less p, CI high", c(tl$p.value, tl$conf.int[2]))
tg <- t.test(extra ~ group, data = sleep, alternative = "greater")
p("welch greater p, CI low", c(tg$p.value, tg$conf.int[1]))
to <- t.test(x, mu = 0.5)
p("one-sample mu=0.5 t, df, p", c(to$statistic, to$parameter, to$p.value)); p("one-sample CI", to$conf.int)
d <- x - y; p("d_z", mean(d) / sd(d))
sp <- sqrt(((10 - 1) * var(x) + (10 - 1) * var(y)) / 18); p("cohen d pooled", (mean(x) - mean(y)) / sp)
J <- function(m) exp(lgamma(m / 2) - lgamma((m - 1) / 2)) / sqrt(m / 2)
p("hedges g (m=18)", J(18) * (mean(x) - mean(y)) / sp)
ws <- suppressWarnings(wilcox.test(x, y, paired = TRUE))
p("sleep wilcoxon paired V, p", c(ws$statistic, ws$p.value))
wm <- suppressWarnings(wilcox.test(extra ~ group, data = sleep))
p("sleep mann-whitney W, p", c(wm$statistic, wm$p.value))

cat("== PlantGrowth one-way ==\n")
a <- anova(lm(weight ~ group, data = PlantGrowth))
p("F, df1, df2, p", c(a$`F value`[1], a$Df[1], a$Df[2], a$`Pr(>F)`[1]))
p("SS group, SS error", a$`Sum Sq`)

cat("== exact Wilcoxon signed rank (no ties, no zeros) ==\n")
wx <- c(1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30)
wy <- c(0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29)
w1 <- wilcox.test(wx, wy, paired = TRUE); p("V, p two-sided", c(w1$statistic, w1$p.value))
p("p greater", wilcox.test(wx, wy, paired = TRUE, alternative = "greater")$p.value)
p("p less", wilcox.test(wx, wy, paired = TRUE, alternative = "less")$p.value)

cat("== Wilcoxon with ties and a zero (normal approx) ==\n")
tx <- c(5, 7, 7, 9, 3, 4, 8, 8, 6, 2)
ty <- c(3, 5, 5, 9, 4, 1, 6, 5, 3, 2)
w2 <- suppressWarnings(wilcox.test(tx, ty, paired = TRUE)); p("V, p", c(w2$statistic, w2$p.value))

cat("== Mann-Whitney exact ==\n")
mx <- c(0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46)
my <- c(1.15, 0.88, 0.90, 0.74, 1.21)
m1 <- wilcox.test(mx, my); p("W, p", c(m1$statistic, m1$p.value))
p("p greater", wilcox.test(mx, my, alternative = "greater")$p.value)
cat("== Mann-Whitney ties ==\n")
ux <- c(1, 2, 2, 3, 3, 3, 4, 5); uy <- c(3, 4, 4, 5, 5, 6, 6)
m2 <- suppressWarnings(wilcox.test(ux, uy)); p("W, p", c(m2$statistic, m2$p.value))

cat("== Friedman (RoundingTimes, R's ?friedman.test) ==\n")
RoundingTimes <- matrix(c(5.40, 5.50, 5.55, 5.85, 5.70, 5.75, 5.20, 5.60, 5.50, 5.55, 5.50, 5.40,
  5.90, 5.85, 5.70, 5.45, 5.55, 5.60, 5.40, 5.40, 5.35, 5.45, 5.50, 5.35, 5.25, 5.15, 5.00,
  5.85, 5.80, 5.70, 5.25, 5.20, 5.10, 5.65, 5.55, 5.45, 5.60, 5.35, 5.45, 5.05, 5.00, 4.95,
  5.50, 5.50, 5.40, 5.45, 5.55, 5.50, 5.55, 5.55, 5.35, 5.45, 5.50, 5.55, 5.50, 5.45, 5.25,
  5.65, 5.60, 5.40, 5.70, 5.65, 5.55, 6.30, 6.30, 6.25), nrow = 22, byrow = TRUE)
f <- friedman.test(RoundingTimes); p("chisq, df, p", c(f$statistic, f$parameter, f$p.value))

cat("== one-way repeated measures, 4 levels, 8 subjects ==\n")
rm <- matrix(c(30, 28, 16, 34,
               14, 18, 10, 22,
               24, 20, 18, 30,
               38, 34, 20, 44,
               26, 28, 14, 30,
               12, 16, 11, 20,
               29, 25, 15, 37,
               20, 22, 13, 25), nrow = 8, byrow = TRUE)
fit <- lm(rm ~ 1)
sph <- anova(fit, X = ~1, test = "Spherical")
p("F, df1, df2, p", c(sph$F[1], sph$`num Df`[1], sph$`den Df`[1], sph$`Pr(>F)`[1]))
p("p GG, p HF", c(sph$`G-G Pr`[1], sph$`H-F Pr`[1]))
sp <- stats:::sphericity(SSD(fit), X = ~1, idata = data.frame(index = 1:4))
p("R stats GG eps, HF eps", c(sp$GG.eps, sp$HF.eps))
mt <- mauchly.test(fit, X = ~1); p("Mauchly W, p (R stats)", c(mt$statistic, mt$p.value))
long <- data.frame(s = factor(rep(1:8, 4)), w = factor(rep(1:4, each = 8)), y = as.vector(rm))
av <- summary(aov(y ~ w + Error(s/w), data = long))
ssw <- av$`Error: s:w`[[1]]$`Sum Sq`; sss <- av$`Error: s`[[1]]$`Sum Sq`
p("SS w, SS error(s:w), SS subjects", c(ssw, sss))
p("eta2 generalized", ssw[1] / (ssw[1] + ssw[2] + sss))
A <- Anova(fit, idata = data.frame(w = factor(1:4)), idesign = ~w, type = 3)
sA <- summary(A, multivariate = FALSE)
p("car GG eps, HF eps", c(sA$pval.adjustments[, "GG eps"], sA$pval.adjustments[, "HF eps"]))
p("car mauchly W, p", sA$sphericity.tests)

cat("== two within factors 2 x 3, 6 subjects ==\n")
tw2 <- data.frame(s = factor(rep(1:6, each = 6)), a = factor(rep(rep(c("a1", "a2"), each = 3), 6)),
                  b = factor(rep(c("b1", "b2", "b3"), 12)),
                  y = c(12, 15, 19, 10, 14, 21,
                        9, 13, 14, 11, 12, 18,
                        14, 16, 22, 13, 17, 25,
                        10, 10, 15, 9, 13, 17,
                        11, 15, 18, 12, 16, 24,
                        8, 12, 16, 9, 10, 20))
wide <- matrix(tw2$y, nrow = 6, byrow = TRUE)
fit2 <- lm(wide ~ 1)
A2 <- Anova(fit2, idata = expand.grid(b = factor(c("b1", "b2", "b3")), a = factor(c("a1", "a2")))[, c(2, 1)],
            idesign = ~a * b, type = 3)
s2 <- summary(A2, multivariate = FALSE)
u <- unclass(s2$univariate.tests); p("F a, b, a:b", u[2:4, 5]); p("p a, b, a:b", u[2:4, 6])
print(s2$univariate.tests, digits = 15)
print(s2$pval.adjustments, digits = 15)
print(s2$sphericity.tests, digits = 15)
write.csv(tw2, "/tmp/two_within.csv", row.names = FALSE)

cat("== mixed: group (n = 4, 5) x time (3 levels) ==\n")
mixed <- data.frame(s = factor(rep(1:9, each = 3)), g = factor(rep(c(rep("ctrl", 4), rep("trt", 5)), each = 3)),
                    time = factor(rep(c("t1", "t2", "t3"), 9)),
                    y = c(10, 12, 15, 8, 11, 11, 12, 14, 18, 9, 9, 13,
                          11, 16, 22, 13, 17, 20, 10, 15, 19, 12, 19, 25, 14, 18, 21))
mw <- matrix(mixed$y, nrow = 9, byrow = TRUE); grp <- factor(c(rep("ctrl", 4), rep("trt", 5)))
options(contrasts = c("contr.sum", "contr.poly"))
fit3 <- lm(mw ~ grp)
for (ty in c(2, 3)) {
  A3 <- Anova(fit3, idata = data.frame(time = factor(c("t1", "t2", "t3"))), idesign = ~time, type = ty)
  s3 <- summary(A3, multivariate = FALSE)
  cat("type", ty, "\n"); u <- unclass(s3$univariate.tests); p("F grp, time, grp:time", u[2:4, 5]); p("p grp, time, grp:time", u[2:4, 6])
  print(s3$univariate.tests, digits = 15); print(s3$pval.adjustments, digits = 15)
  print(s3$sphericity.tests, digits = 15)
}
av3 <- summary(aov(y ~ g * time + Error(s/time), data = mixed)); print(av3, digits = 15)
write.csv(mixed, "/tmp/mixed.csv", row.names = FALSE)

cat("== unbalanced between 2 x 3 ==\n")
ub <- data.frame(a = factor(c("x", "x", "x", "x", "x", "x", "x", "y", "y", "y", "y", "y", "y", "y", "y", "y")),
                 b = factor(c("p", "p", "q", "q", "q", "r", "r", "p", "q", "q", "r", "r", "r", "r", "p", "p")),
                 y = c(4.1, 5.3, 6.2, 5.9, 7.1, 8.0, 7.4, 3.2, 5.5, 4.8, 9.1, 8.7, 9.9, 8.2, 3.9, 4.4))
for (ty in c(2, 3)) {
  cat("type", ty, "\n"); an <- Anova(lm(y ~ a * b, data = ub), type = ty); print(an, digits = 15)
  p("F", an$`F value`); p("p", an$`Pr(>F)`)
}
write.csv(ub, "/tmp/unbalanced.csv", row.names = FALSE)

cat("== extreme tails ==\n")
p("pnorm(-37)", pnorm(-37)); p("pt(-200, 50)", pt(-200, 50)); p("pt(-1e10, 30) ", pt(-1e10, 30))
p("pf(5000, 3, 400, lower=F)", pf(5000, 3, 400, lower.tail = FALSE))
p("pchisq(1300, 2, lower=F)", pchisq(1300, 2, lower.tail = FALSE))
big <- c(0, 1, 2, 3) * 1e-3 + 1e9; p("psignrank(0, 40)", psignrank(0, 40)); p("pwilcox(0, 45, 45)", pwilcox(0, 45, 45))
