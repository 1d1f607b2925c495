// slider_mjcf.h: the tests' one-PAM slider: a body on a slide joint pulled by one PAM
// actuator on a fixed tendon (tendon length = qpos, moment arm 1), no gravity. Tests that need
// more userdata or another time step replace the attributes in the text (the <size> element
// is `nuserdata="2"`, the option `gravity="0 0 0"`).
#pragma once

namespace pamsim_test {

inline constexpr char kSliderXml[] = R"(
<mujoco>
  <size nuserdata="2"/>
  <option gravity="0 0 0"/>
  <worldbody>
    <body>
      <joint name="slide" type="slide" axis="1 0 0"/>
      <geom type="sphere" size="0.01" mass="1"/>
    </body>
  </worldbody>
  <tendon><fixed name="t"><joint joint="slide" coef="1"/></fixed></tendon>
  <actuator>
    <general name="pam" tendon="t" biastype="user" gaintype="fixed" gainprm="0"
             forcelimited="true" forcerange="-5000 0"/>
  </actuator>
</mujoco>)";

}  // namespace pamsim_test
