#include "app/common/study_citation.hpp"

#include <utility>

namespace tribolab::app {

std::string study_citation(Study study) {
  switch (study) {
    case Study::incline:
      return "The incline study: 林亮昕 (advisor 吳旭峯), National Yilan Senior High School, "
             "「斜面二維運動與摩擦力的探討」 (“Two-dimensional motion on an incline and friction”), "
             "57th Taiwan National Primary and High School Science Fair (中華民國第57屆中小學科學展覽會), "
             "2017, senior high school physics and astronomy, entry 051814, third place.";
    case Study::rugby_ball:
      return "The rugby-ball study: 陳顥帆, 吳振宇, 詹仲睿 (advisor 高銘宏), The Affiliated Senior High "
             "School of National Taiwan Normal University, 「有角速度之橄欖球的運動行為分析」 (“Analysis "
             "of the motion of a rugby ball with angular velocity”), 61st Taiwan National Primary and "
             "High School Science Fair (中華民國第61屆中小學科學展覽會), 2021, senior high school physics "
             "and astronomy, entry 051804, third place.";
  }
  return {};
}

report::Report with_study_source(report::Report r, Study study) {
  r.add_section("Source").add_paragraph(
      study_citation(study) + " Figure, table and equation numbers in this report are the study's own, "
      "with the paper's Chinese numerals beside their reading, e.g. equation 10A (十A).");
  return r;
}

}  // namespace tribolab::app
