// Gives the XML language the `pov:` library compiled into this program (a program that
// reads XML scenes calls it once before it reads one; without it `pov:` names are errors).
#pragma once

namespace lucent {

void registerPovLibrary();

}  // namespace lucent
