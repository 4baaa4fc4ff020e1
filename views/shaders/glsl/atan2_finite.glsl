// SPDX-License-Identifier: BSD-3-Clause
// mirrors std::atan2, which generated formulas call as lcAtan2 (core/codegen): GLSL leaves
// atan(0, 0) undefined (llvmpipe gives 3 pi / 4) where std::atan2 gives 0.
float lcAtan2(float y, float x)
{
  return (x == 0.0 && y == 0.0) ? 0.0 : atan(y, x);
}
