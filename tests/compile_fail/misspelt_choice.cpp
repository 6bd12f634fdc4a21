// A choice is an enum's name table (common/params/params.h), so a misspelt choice is a misspelt enumerator: compiled by
// tests/check_misspelt_choice.cmake as it stands, which must compile, and with each GSV_MISSPELT_* defined, which must
// not. Before, a choice was read as text and compared with a literal, which compiled whatever its spelling.
#include "common/params/params.h"
#include "support/flow/flow_field.h"
#include "support/particles/particle_motion.h"

namespace {

enum class Field { File };
constexpr gsv::EnumName<Field> kFields[] = {{Field::File, "file"}};

}  // namespace

int main() {
    gsv::Params p;
    const auto integrator = p.add_enum("integrator", gsv::Integrator::Euler, gsv::kIntegratorNames, "the step");
    const auto field = p.add_enum("field", gsv::UnsteadyKind::DoubleGyre, gsv::kUnsteadyKindNames, kFields, "the flow");
#if defined(GSV_MISSPELT_COMPARISON)
    const bool fine = integrator.get() == gsv::Integrator::Rk5;  // rk5: no such integrator
#elif defined(GSV_MISSPELT_CONDITION)
    p.add_float("gravity", 2, 0, 20, "downward").applies_when(integrator, {gsv::Integrator::Midpiont});
    const bool fine = true;
#elif defined(GSV_MISSPELT_ONE_OF)
    const bool fine = field.get() == Field::Fiel;
#elif defined(GSV_MISSPELT_WRONG_ENUM)
    const bool fine = integrator.get() == gsv::ParticleScene::Abc;  // a value of another choice
#else
    p.add_float("gravity", 2, 0, 20, "downward").applies_when(integrator, {gsv::Integrator::Midpoint});
    const bool fine = integrator.get() == gsv::Integrator::Rk4 || field.get() == Field::File ||
                      field.get() == gsv::UnsteadyKind::VortexStreet;
#endif
    return fine ? 0 : 1;
}
