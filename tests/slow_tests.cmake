# The label `slow`: the suite's tests that take ten seconds and more in the
# sanitizer build (scripts/sanitize: -O1 with AddressSanitizer and
# UndefinedBehaviorSanitizer, where Eigen's dense algebra and the solved
# collision run 30 to 40 times slower than in Release). Each is a large
# instance (a fine mesh, a grid of thousands of points, a thousand steps) of
# code that smaller tests cover under the sanitizers too; scripts/sanitize
# leaves them out and scripts/test runs them on the Release build. Read by
# ctest after the discovered tests (tests/CMakeLists.txt); ctest passes over a
# name no test has, so the test "tests: every slow name is a test"
# (check_slow_tests.cmake) counts them.
foreach(name IN ITEMS
    "core:The dense state-space solve of a fine mesh drops none of the low modes"
    "core:A linear ball on strings lasts pi sqrt(mu/k) with k the two springs in series"
    "core:Rigid strings on a rigid frame give the ball's own COR and contact time"
    "hard:Meshes of 2000 elements keep f1 within discretisation plus 8.4 N^4 eps round-off"
    "hard:Held in the hand, 2000 elements keep f1 within round-off of the converged value"
    "studies:Study 1: the optimizer agrees with a 5^6 grid and the paper's bottom row of Table I"
    "studies:Study 7: lead tape for power with the solved collision in the loop, against a grid"
    "studies:Targets lead cannot reach give the nearest specs a grid search finds"
    "reports:Reports only render: no file in src/reports/ evaluates, solves, searches or sweeps")
  set_tests_properties("${name}" PROPERTIES LABELS slow)
endforeach()
