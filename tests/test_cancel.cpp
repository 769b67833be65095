// The cancel function of the progress hook (kernel/progress.h), which the Python
// binding uses for Ctrl-C: a method asked to stop returns Code::runtime "cancelled" at its next
// progress point, and a hook that never asks changes nothing.
#include <catch2/catch.hpp>

#include <string>

#include "api/erd.h"
#include "tests/output_util.h"

using namespace erd;

namespace {

struct Counter {
    int calls = 0;
    int stop_after = 0;  // cancel from this call on; 0 = never
};

ProgressHook counting_hook(Counter* c) {
    ProgressHook h;
    h.ctx = c;
    h.fn = [](void* ctx, const char*, double) { ++static_cast<Counter*>(ctx)->calls; };
    h.cancel = [](void* ctx) {
        const Counter* k = static_cast<Counter*>(ctx);
        return k->stop_after > 0 && k->calls >= k->stop_after;
    };
    return h;
}

}  // namespace

TEST_CASE("a progress hook's cancel stops the methods with 'cancelled'", "[cancel]") {
    const Image image = output_test::wave_disc_image();
    const api::ImageView view = api::view_of(image);
    for (api::Method m : {api::Method::gpi, api::Method::erded, api::Method::erdgpi}) {
        INFO(api::method_name(m));
        api::Options plain;
        plain.generate.density = 2.0;
        plain.generate.density_given = true;
        Model ref;
        REQUIRE(api::generate(m, view, plain, &ref).ok());

        Counter never;
        api::Options watched = plain;
        watched.generate.progress = counting_hook(&never);
        Model same;
        REQUIRE(api::generate(m, view, watched, &same).ok());
        CHECK(never.calls > 0);
        CHECK(same.vertices == ref.vertices);
        CHECK(same.corner_values == ref.corner_values);

        for (int stop_after : {1, 2}) {  // the first points of GPI (1% steps) and of the ERD methods (step 1)
            Counter c;
            c.stop_after = stop_after;
            api::Options cancelled = plain;
            cancelled.generate.progress = counting_hook(&c);
            Model out;
            const Status st = api::generate(m, view, cancelled, &out);
            CHECK(st.code == Code::runtime);
            CHECK(st.message == kCancelled);
            CHECK(c.calls <= stop_after);
        }
    }
}
