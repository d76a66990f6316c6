#pragma once
// The table `pond bench` prints: the machine and the device, then each figure's median and spread
// (least and most of its samples), its hash or triangles where it has them, and the notes.
#include "app/bench/report.h"

namespace pond::bench {

void print_table(const Report& report);

}  // namespace pond::bench
