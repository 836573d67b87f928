// Shared constants.
const float kPi = 3.14159265358979;
const float kHalfPi = 1.57079632679490;
const float kInvPi = 0.31830988618379;
