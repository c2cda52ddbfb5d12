! The box of tests/openfoam/box in Code_Saturne: the one setting Code_Saturne
! 6.0 offers only in Fortran. ipstdv(ipstfo) = 1 makes the solver compute the
! field "boundary_forces" (the force of the fluid on each boundary face), from
! which SnowWall's shear gate reads the wall shear stress (swcs.c).
subroutine usipsu(nmodpp)
use entsor
implicit none
integer nmodpp
ipstdv(ipstfo) = 1
return
end subroutine usipsu
