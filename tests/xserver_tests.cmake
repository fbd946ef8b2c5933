# Read by CTest after the discovered GoogleTest tests (TEST_INCLUDE_FILES): the tests that
# start their own Xvfb (tests/player/xvfb_support.h) share one lock, so `ctest -j` never
# runs two of them at once. Two servers started at the same moment under ctest -j2 have
# left a test talking to a display it could not open ("server already running", then
# "X11: Failed to open display"); CPU and headless GL tests still run beside them.
set_tests_properties(
  DisplayWindowTest.FullscreenShowsTheHeadlessEiaPixelForPixel
  DisplayWindowTest.MismatchedMonitorIsRefusedOrCentredUnscaled
  DisplayWindowTest.CameraControlsAndPreviewFromMouseAndKeys
  DisplayWindowTest.QuiltInputFullscreenEqualsItsHeadlessEia
  DisplayWindowTest.ReadoutTogglesOverTheWindowAndStaysOutOfScreenshots
  DisplayWindowTest.ReadoutOnThePanelOnlyWhenAsked
  WindowSmoke.RendersEveryOutputAndSavesScreenshotsUnderXvfb
  WindowSmoke.KeysAndMouseSwitchRendererOutputViewerAndPause
  PROPERTIES RESOURCE_LOCK xvfb)
