const float kPi = 3.14159265358979323846;
const float kInvPi = 0.31830988618379067154;
const float kTwoPi = 6.28318530717958647692;
const float kInfinity = 1.0 / 0.0;
