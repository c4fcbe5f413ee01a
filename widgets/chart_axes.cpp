#include "widgets/chart_axes.h"

#include <cmath>
#include <initializer_list>

namespace resect {

double niceStep(double v) {
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= v * (1 - 1e-9))
            return m * p;
    return 10 * p;
}

} // namespace resect
