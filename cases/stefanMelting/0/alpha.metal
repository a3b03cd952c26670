/*--------------------------------*- C++ -*----------------------------------*\
  ldnaFoam test case: 1D melting (two-phase Neumann problem)
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
internalField   uniform 1;
boundaryField
{
    hotWall { type zeroGradient; }
    farEnd  { type inletOutlet; inletValue uniform 1; value uniform 1; }
    sides   { type empty; }
}

// ************************************************************************* //
