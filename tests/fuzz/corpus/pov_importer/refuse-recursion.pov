#macro R(N) R(N + 1) #end
R(0)
