# Read by ctest after the discovered tests: the longest start first (COST), so
# that a cold run, with no Testing/Temporary/CTestCostData.txt yet, does not end
# on one of them running alone. Seconds under the sanitizers (clang), roughly; ctest's own
# measurements replace these once it has run the suite.
foreach(entry
    "62|ShippedWorlds/Culling.NeverHidesWhatTheFrameShowsOnAnyFrameOfTheShippedPaths/\"caves\""
    "59|FlythroughChunks.ConcurrentChunksMatchASingleRun"
    "57|Occupancy.EditsStagedThroughALiveSceneKeepGpuAndCpuInStep"
    "42|LightBake.OneGlowingVoxelInAClosedDarkRoomMatchesThePathTracer"
    "31|CliErrors.AccumulatedStillIsLessNoisyAndCloserToTheReference"
    "23|Regression.CavesCarveASphere"
    "23|Gtao.NumericalExtremesStayFinite"
    "22|Regression.RoomsDigThroughAWall"
    "22|CliErrors.FlythroughSplitRunMatchesTheWholeRun"
    "21|CliErrors.TradeoffWritesEveryMethodAndPreset"
    "20|Regression.CavesWalk"
    "20|CliErrors.ViewerPlaysAPathsEditsAsFlythroughDoes"
    "19|Tune.FitsVbaosOwnSettings"
    "19|CliErrors.AccumulatedHistoryCountsEveryFrame"
    "18|VoxelRays.RaysThroughEdgesAndCornersOfSolidVoxelsAndThinWallsAreBlocked"
    "18|ObjectLight.ABoxOnTheGridLightsTheSceneAsTheSameVoxelsInTheWorld"
    "18|LightBake.ARoomLitOffASunlitPatchMatchesThePathTracerEverywhere"
    "18|CliErrors.StabilityBaselineCatchesARegressionAndRefusesAnotherRun"
    "17|Mesher.OneQuadPerExposedFace"
    "16|Regression.YardWatch"
    "16|ObjectLight.AnObjectInALampLitRoomShadowsItAsThePathTracerDoes"
    "15|WorldSave.InterruptedSaveLeavesTheOldFile"
    "15|Tune.ReportsAFitNoWorseThanTheDefaultsAndReproducesIt"
    "14|Regression.ThinFence"
    "14|CliErrors.ViewerPlaysAWorldPathAsFlythroughRendersIt"
    "13|SoftSun.StillCameraConvergesToTheVisibleFractionOfTheDisc"
    "13|SoftSun.HistoryFollowsTheSurfaceAsTheCameraMoves"
    "13|Regression.RoomsOrbit"
    "13|Mesher.QuadsMeetCornerToCornerWithinAndAcrossChunksAtEveryLevel"
    "13|FlythroughVideo.AnFfmpegThatNeverStartsReadingIsGivenUpSoon"
    "13|FlythroughChunks.BakedChunksNeedNoWarmUpAndAreOneRunExactly"
    "13|Compare.DrawsAndTracesTheWorldsObjects"
    "13|CliErrors.StabilityBaselineCatchesAChangedImage"
    "12|LightEdit.LampsPlacedAndWallsBuiltInALitRoomMatchAFreshBake"
    "12|HostileFlythrough.ARunRefusedForABadBakeLeavesTheDirectoryAsItWas"
    "12|Gtao.FlatFloorStaysOpenFromStraightDownToGrazing"
    "12|GpuTest.RenderMemoryEstimateMatchesTheTargetsOfEveryShape")
  string(REPLACE "|" ";" entry "${entry}")
  list(GET entry 0 cost)
  list(GET entry 1 name)
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endforeach()
