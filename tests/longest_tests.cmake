# Read by ctest after the discovered tests: the longest start first (COST), so
# that a cold run, with no Testing/Temporary/CTestCostData.txt yet, does not end
# on one of them running alone. Seconds under the sanitizers, roughly; ctest's own
# measurements replace these once it has run the suite.
foreach(entry
    "150|FlythroughChunks.ConcurrentChunksMatchASingleRun"
    "75|ShippedWorlds/Culling.NeverHidesWhatTheFrameShowsOnAnyFrameOfTheShippedPaths/\"caves\""
    "65|CliErrors.AccumulatedStillIsLessNoisyAndCloserToTheReference"
    "58|CliErrors.FlythroughSplitRunMatchesTheWholeRun"
    "49|Occupancy.EditsStagedThroughALiveSceneKeepGpuAndCpuInStep"
    "42|LightBake.OneGlowingVoxelInAClosedDarkRoomMatchesThePathTracer"
    "40|Regression.CavesCarveASphere"
    "39|Regression.CavesWalk"
    "37|CliErrors.AccumulatedHistoryCountsEveryFrame"
    "36|FlythroughChunks.BakedChunksNeedNoWarmUpAndAreOneRunExactly"
    "34|CliErrors.TradeoffWritesEveryMethodAndPreset"
    "33|Gtao.NumericalExtremesStayFinite"
    "33|CliErrors.ViewerPlaysAPathsEditsAsFlythroughDoes"
    "31|Regression.RoomsDigThroughAWall"
    "31|CliErrors.StabilityBaselineCatchesARegressionAndRefusesAnotherRun"
    "30|ObjectLight.ABoxOnTheGridLightsTheSceneAsTheSameVoxelsInTheWorld"
    "26|HostileFlythrough.ChunksOfOtherBakesAreRefused"
    "24|LightBake.ARoomLitOffASunlitPatchMatchesThePathTracerEverywhere"
    "24|FlythroughChunks.AKilledRunRerunEndsWithEveryFrameRecorded"
    "23|CliErrors.StabilityBaselineCatchesAChangedImage"
    "22|CliErrors.ViewerPlaysAWorldPathAsFlythroughRendersIt")
  string(REPLACE "|" ";" entry "${entry}")
  list(GET entry 0 cost)
  list(GET entry 1 name)
  set_tests_properties("${name}" PROPERTIES COST ${cost})
endforeach()
