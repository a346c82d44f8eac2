// One pass of a compass search (floating point, guesses only): from x, each trial point
// moved(x, d) for the directions d in turn replaces x when it lowers f by more than 1e-15. The
// lattice searches (problems/guess/lattice_search.cpp, problems/star/star_disk.cpp) halve their step after
// a pass that found nothing.
#pragma once
#include <vector>

namespace superpack {

template <class Point, class Move, class Objective>
bool compass_pass(Point& x, double& value, const std::vector<Point>& directions, const Move& moved, const Objective& f,
                  long& evaluations) {
    bool improved = false;
    for (const Point& d : directions) {
        const Point trial = moved(x, d);
        const double trial_value = f(trial);
        ++evaluations;
        if (trial_value < value - 1e-15) {
            x = trial;
            value = trial_value;
            improved = true;
        }
    }
    return improved;
}

}  // namespace superpack
