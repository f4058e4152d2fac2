# Writes the library's XML text (XML) into a C++ source (CPP) as one raw string.
file(READ ${XML} content)
file(WRITE ${CPP} "// Made by povlib/embed.cmake from pov_library.xml: do not edit.\n#include <string_view>\nnamespace lucent {\nextern const std::string_view kPovLibraryXml = R\"POVLIB(${content})POVLIB\";\n}\n")
