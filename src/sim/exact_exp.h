#pragma once
// exp(x) in double from +, -, * and exact scaling only, so a perturbation's weight table has the same
// bits on x86-64 and on IA-32 (whose libm may use x87 code) and on any compiler. Accuracy: a few ulp
// of double, far below the float the weights are rounded to.
namespace pond::sim {

double exact_exp(double x);

}  // namespace pond::sim
