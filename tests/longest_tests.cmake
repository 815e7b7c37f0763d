# Read by ctest after the discovered tests: the longest start first (COST), so
# that a cold run, with no Testing/Temporary/CTestCostData.txt yet, does not end
# on one of them running alone. Seconds under the sanitizers (clang), roughly; ctest's own
# measurements replace these once it has run the suite.
foreach(entry
    "161|Occupancy.EditsStagedThroughALiveSceneKeepGpuAndCpuInStep"
    "114|ShippedWorlds/Culling.NeverHidesWhatTheFrameShowsOnAnyFrameOfTheShippedPaths/\"caves\""
    "98|LightBake.OneGlowingVoxelInAClosedDarkRoomMatchesThePathTracer"
    "83|FlythroughChunks.ConcurrentChunksMatchASingleRun"
    "72|ObjectLight.ABoxOnTheGridLightsTheSceneAsTheSameVoxelsInTheWorld"
    "47|Regression.CavesCarveASphere"
    "45|Regression.CavesWalk"
    "43|CliErrors.TradeoffWritesEveryMethodAndPreset"
    "43|CliErrors.AccumulatedStillIsLessNoisyAndCloserToTheReference"
    "40|Regression.RoomsDigThroughAWall"
    "40|Gtao.NumericalExtremesStayFinite"
    "36|ObjectLight.AnObjectInALampLitRoomShadowsItAsThePathTracerDoes"
    "35|SoftSun.HistoryFollowsTheSurfaceAsTheCameraMoves"
    "34|CliErrors.AccumulatedHistoryCountsEveryFrame"
    "33|CliErrors.FlythroughSplitRunMatchesTheWholeRun"
    "32|HostileFlythrough.ChunksOfOtherBakesAreRefused"
    "29|LightBake.ARoomLitOffASunlitPatchMatchesThePathTracerEverywhere"
    "26|FlythroughChunks.AKilledRunRerunEndsWithEveryFrameRecorded"
    "26|CliErrors.ViewerPlaysAPathsEditsAsFlythroughDoes"
    "24|SoftSun.StillCameraConvergesToTheVisibleFractionOfTheDisc"
    "24|GpuTest.RenderMemoryEstimateMatchesTheTargetsOfEveryShape"
    "24|FaceCache.PointSunVisibilityIsTheLitShareOfTheTexelsSquare")
  string(REPLACE "|" ";" entry "${entry}")
  list(GET entry 0 cost)
  list(GET entry 1 name)
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endforeach()
