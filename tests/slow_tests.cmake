# The tests labelled "slow": the corpus and random-family runs that take
# seconds each in a Release build (minutes under the sanitizers). The Release
# half of CI runs every test; the ASan + UBSan half runs `ctest -LE slow`, which
# still exercises every module through its fast unit tests.
# A gtest filter: patterns joined by ':' (test names as ctest lists them).
set(pqmesh_slow_patterns
  # 3D mesher: random families and corpus runs
  "Shards/RandomPolyhedraEveryRun.*"
  "Shards/FlatEdgesRandom.*"
  "BoundedSeeds/WorstEdgeBox.*"
  "RandomPolyhedraSuite.*"
  "WorstBoxFreeze.*"
  "WarpCandidates.SameRowsInSameOrderAsPlainConstructionOnModels"
  "Warp/FacetBoxes.HalfSpaceThroughRandomTreesIsMeshedConformingly/*"
  "Warp/CorpusLemma6.*"
  "VertexBoxNotchSquare.TwoNotchEdgesThroughOneSquareMeshValid"
  "TwoConePoints.EdgeBoxAcrossAPushedFaceIsNotFrozen"
  "RebuildLoop.PartialTrialsMakeTheMeshOfFullTrials"
  "FlatEdges.SquaresSplitByPlaneGroupsAtAVertex"
  "FlatEdges.ChannelWithAHeaterPatchFromTheCorpus"
  "FlatConeTwoApex.ApexAlmostOnABoxFaceIsConedFromTwoPoints"
  "EdgeFacetFans.FlatEdgeBoxGetsFacetFanPoints"
  "EnclosingRadiusFilter.NearlyEqualEdgesMatchTheFullSearch"
  "GenericGeodesic.TuningForkCountIndependentOfTheNeckWidth"
  # octree and cube components: oracles over random polyhedra and the corpus
  "OctreeInvariantsRandom.*"
  "OctreeGeodesic.*"
  "OctreeAdjacency.BalanceAdjacentMatchesComponentsFromScratch"
  "LargeCorpus/OctreeCorpus.*"
  "Corpus/OctreeCorpus.*"
  "Corpus/OctreeInvariantsCorpus.*"
  "CubeComponentsOracle.*"
  "CubeRimsOracle.*"
  "TreePerf.MillionLeavesOctree"
  # lfs and size bounds
  "Lfs3Integral.GrowsAsAGapNarrows"
  "Lfs3Integral.ConvergesUnderRefinement"
  "Lfs3.FastEqualsBruteOnRandomPolyhedra"
  "LfsPerf.*"
  "LfsIntegral.CorpusConverges"
  "SizeRatio.MatchesBruteForceOnTheLBlock"
  # 2D: random polygon families
  "NoSteinerTriangulation.RandomPolygonsWithHoles*"
  "NoSteinerTriangulation.HardCases"
  "SteinerFreeOracle.RandomPolygonsWithHoles"
  "ShrinkR.RandomPolygonsWithHoles"
  "MatchQR.RandomPolygonsWithHoles"
  "QualityPass.LargeCavitiesLiftTheStuckRandomPolygonsToTheCdt"
  "QualityPass.ConstructionMeshesOfCorpus"
  "QuadMeshProperty.RandomPolygonsAreValidAndWellShaped"
  "QuadMeshProperty.HardGeneratorSettingsAreValid"
  "MeshPolygonProperty.RandomPolygonsCertifiedAndNoLargerThanTheQuadtreeMesh"
  "MeshPolygonProperty.HardGeneratorSettingsCertified"
  "Components2dProperty.AgainstGridOracle"
)
list(JOIN pqmesh_slow_patterns ":" PQMESH_SLOW_TESTS)
