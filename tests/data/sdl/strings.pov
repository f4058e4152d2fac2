// Strings: str() formats, vstr, the string functions, escapes, comparisons.
#version 3.7;
#debug concat(str(1/3, 0, -1), "|", str(-7.5, 5, 2), "|", str(3, -5, 0), "\n")
#debug concat(str(12345.678, 0, 3), "|", str(0.5, 0, 0), "|", str(2.5, 0, 0), "\n")
#debug concat(str(-0.0001, 0, 2), "|", str(1e20, 0, 1), "|", str(7, 10, -1), "\n")
#debug concat(str(1e300, 0, 2), "\n")
#debug concat(vstr(2, <1, 2, 3>, ", ", 0, 1), "|", vstr(4, <1, 2, 3>, "/", 3, 0), "\n")
#debug concat(vstr(3, 5, ";", 0, 2), "\n")
#debug concat(substr("Hello world", 7, 5), "|", strupr("MiXed"), "|", strlwr("MiXed"), "\n")
#debug concat(chr(65), chr(98), "|", str(asc(chr(90)), 0, 0), "\n")
#debug "tab\there\\slash \"quoted\" \'single\'\n"
#declare S = concat("a", "b", "c");
#debug concat(S, " ", str(strlen(S), 0, 0), "\n")
#if ("abc" < "abd") #debug "less\n" #end
#if (S = "abc") #debug "equal\n" #end
#if (S != "abd") #debug "different\n" #end
#debug concat(datetime(0), "\n")
#debug concat(datetime(1.5, "%Y/%m/%d %H"), "\n")
#declare T = S;
#declare T = concat(T, T);
#debug concat(S, " ", T, "\n")
#debug concat(substr("abc", 1, 0), "|", substr("abc", 3, 1), "\n")
// str() past POV-Ray's 254-character buffer: %g instead, or <invalid>; a precision of
// 10^8 must not take seconds.
#debug concat("[", str(9, 0, 66666666), "]\n")
#debug concat("[", str(-2.5, 0, 400), "]\n")
#debug concat("[", str(1/3, 0, 280), "]\n")
#debug concat("[", str(7, 400, 2), "]\n")
