# Reference values for tests/analysis/r_offset_test.cpp: data offset by 1e6, 1e9 and 1e12 with a
# spread of about 1e-3, analysed by R 4.2.2 (Debian 12 r-base-core). Run:
#   Rscript tests/analysis/reference/offset_r_reference.R
# The data are off + k * u for the integers k below and u = 2^-20 (sd about 1e-3), at 1e12 also
# u = 2^-10 (sd about 1): the same IEEE double operations in R and C++, so both analyse the same
# doubles. At 1e12 with u = 2^-20 R's t.test stops ("data are essentially constant": the standard
# error is below 10 eps |mean|); tlab refuses the same way. Numbers are printed to 17 digits.
a <- c(398, -1089, 378, -129, -2388, -398, 447, -780, -269, -1458, 1484, 704)
b <- c(1858, 2068, 2058, 1854, 2558, 3700, 1229, -1183, 1587, 2189, 2898, 897, 818, 1222, 2393)
g3 <- c(1794, 1130, 287, 1923, 1240, 337, 11, 897, 676, 868)
pre <- c(-657, -1033, 102, -507, -1322, -159, -633, -1378, 325, -925, -296, 852, -3226, 1327)
post <- c(1076, 1119, 2385, 894, 1146, 707, 1852, 145, 1971, 1042, 1342, 1192, 1768, 959)
third <- c(1433, 972, 1591, 689, 775, 1912, 705, 2225, -1270, -71, 881, -2224, -95, 562)
p <- function(label, x) cat(sprintf("%-28s %s\n", label, paste(sprintf("%.17g", x), collapse = ", ")))
tt <- function(label, r) p(label, c(r$statistic, r$parameter, r$p.value, r$conf.int))
cases <- list(c(1e6, 2^-20), c(1e9, 2^-20), c(1e12, 2^-10))
cat("1e12, u = 2^-20:", tryCatch(t.test(1e12 + a * 2^-20, mu = 1e12)$statistic, error = conditionMessage), "\n")
for (case in cases) {
  off <- case[1]; u <- case[2]
  cat(sprintf("== offset %g, u = %g ==\n", off, u))
  x <- off + a * u; y <- off + b * u; z <- off + g3 * u
  p("mean(a) - off, var(a)", c(mean(x) - off, var(x)))
  p("cov(pre, post)", cov(off + pre * u, off + post * u))
  tt("one-sample mu=off", t.test(x, mu = off))
  tt("paired post-pre", t.test(off + post * u, off + pre * u, paired = TRUE))
  tt("student a-b", t.test(x, y, var.equal = TRUE))
  tt("welch a-b", t.test(x, y))
  # One-way between ANOVA. R's aov on the raw values projects 1e12-sized numbers (its QR loses
  # eps*|offset| ~ 1e-4 relative at 1e9 against a spread of 1e-3), so the reference is aov on the
  # values less the offset: an exact subtraction (Sterbenz) and an ANOVA is shift invariant.
  d <- data.frame(y = c(x, y, z) - off, g = factor(rep(c("a", "b", "c"), c(12, 15, 10))))
  s <- summary(aov(y ~ g, data = d))[[1]]
  p("between F, p", c(s$`F value`[1], s$`Pr(>F)`[1]))
  r <- data.frame(y = (off + c(pre, post, third) * u) - off,
                  cond = factor(rep(c("pre", "post", "third"), each = 14)), subj = factor(rep(1:14, 3)))
  s <- summary(aov(y ~ cond + Error(subj / cond), data = r))
  p("within F, p", c(s$`Error: subj:cond`[[1]]$`F value`[1], s$`Error: subj:cond`[[1]]$`Pr(>F)`[1]))
  w <- suppressWarnings(wilcox.test(off + post * u, off + pre * u, paired = TRUE))
  p("wilcoxon paired V, p", c(w$statistic, w$p.value))
  w <- suppressWarnings(wilcox.test(x, y))
  p("mann-whitney W, p", c(w$statistic, w$p.value))
  f <- friedman.test(cbind(off + pre * u, off + post * u, off + third * u))
  p("friedman chi2, p", c(f$statistic, f$p.value))
}
