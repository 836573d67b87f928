// Shared constants.
const float kPi = 3.14159265358979;
const float kInvPi = 0.31830988618379;
