#pragma once
// The accuracy the project asks of an engine against the analytic model (docs/contributing/engines.md): relative error of
// the threshold acceleration and of the period within 0.5 %, of the restitution within 2 % (against Eq. (19) / Housner
// and against the whole-mechanism plastic impact alike). One definition for `vssw compare`, the report and the tests.
namespace vssw::compare {

constexpr double kThresholdTarget = 5e-3;
constexpr double kPeriodTarget = 5e-3;
constexpr double kRestitutionTarget = 2e-2;

}  // namespace vssw::compare
