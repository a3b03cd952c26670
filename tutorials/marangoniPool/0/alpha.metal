/*--------------------------------*- C++ -*----------------------------------*\
  ldnaFoam tutorial: Marangoni flow of a laser pool whose d(sigma)/dT changes sign
\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       volScalarField;
    location    "0";
    object      alpha.metal;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

dimensions      [0 0 0 0 0 0 0];
internalField   uniform 0;
boundaryField
{
    "symmetry."  { type symmetryPlane; }
    walls       { type zeroGradient; }
    atmosphere  { type inletOutlet; inletValue uniform 0; value uniform 0; }
}

// ************************************************************************* //
