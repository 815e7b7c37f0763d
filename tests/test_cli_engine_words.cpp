// The command line names its flags in the engine's errors (the engine names none).
#include "tests/cli_fixture.h"

namespace grotto {
namespace {

using test::CliErrors;

TEST_F(CliErrors, ABentNormalShownWithoutVbaoNamesTheShowFlag) {
    const test::RunResult r = expectRefused(render(good_) + " --ao gtao --show bent_normal", "--show", out());
    EXPECT_NE(r.err.find("--ao vbao"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace grotto
