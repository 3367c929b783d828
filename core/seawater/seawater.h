#pragma once
// Seawater properties for ballast work: EOS-80 density, PSS-78 salinity from
// conductivity, UNESCO 1983 depth <-> pressure. SI-style units are in every
// parameter name; temperatures are ITS-90 unless a TempScale says otherwise.
// Every function validates its inputs and throws auv::InputError naming the
// field and its valid range (seawater/validation.h lists the ranges).
#include "seawater/depth_pressure.h"
#include "seawater/eos80.h"
#include "seawater/pss78.h"
#include "seawater/temperature_scale.h"
#include "seawater/validation.h"
