// SPDX-License-Identifier: BSD-3-Clause
// mirrors std::tanh, which generated metrics call as lcTanh (core/codegen): written as
// sign(x) (1 - e^{-2|x|}) / (1 + e^{-2|x|}), finite for every float x (a driver's tanh may
// overflow to inf / inf for |x| > 44).
float lcTanh(float x)
{
  float e = exp(-2.0 * abs(x));
  return sign(x) * (1.0 - e) / (1.0 + e);
}
