// Catch2 v2 main. Test files are tagged by file name (-#), so ctest can run each alone.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char* argv[]) {
    Catch::Session session;
    session.configData().filenamesAsTags = true;
    const int status = session.applyCommandLine(argc, argv);
    return status != 0 ? status : session.run();
}
