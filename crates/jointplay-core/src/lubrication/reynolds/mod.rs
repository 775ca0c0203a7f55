//! Finite-difference solution of the Reynolds equation (under construction in branch `reynolds`).
