// Text overlay templates: literal pieces and placeholders resolved against the bodies at load,
// braces escaped by doubling, and each kind of mistake an error that quotes the placeholder.
#include "scene/text_template.hpp"

#include <gtest/gtest.h>

namespace tumble::scene {
namespace {

const std::vector<std::string> kBodies = {"cube", "lid.1"};

TextTemplate parsed(std::string_view text) {
  Result<TextTemplate> out = parse_text_template(text, kBodies);
  EXPECT_TRUE(out) << (out ? "" : out.error());
  return out ? *out : TextTemplate{};
}

std::string error_of(std::string_view text) {
  Result<TextTemplate> out = parse_text_template(text, kBodies);
  EXPECT_FALSE(out) << text;
  return out ? "" : out.error();
}

TEST(TextTemplate, SplitsLiteralsAndPlaceholdersInTurn) {
  const TextTemplate t = parsed("\xCF\x89 = {cube.angular_speed:.2f} rad/s   t = {time:.1f} s");
  ASSERT_EQ(t.pieces.size(), 3u);
  ASSERT_EQ(t.values.size(), 2u);
  EXPECT_EQ(t.pieces[0], "\xCF\x89 = ");
  EXPECT_EQ(t.pieces[1], " rad/s   t = ");
  EXPECT_EQ(t.pieces[2], " s");
  EXPECT_EQ(t.values[0].source, Placeholder::Source::body);
  EXPECT_EQ(t.values[0].body, 0u);
  EXPECT_EQ(t.values[0].quantity, BodyQuantity::angular_speed);
  EXPECT_EQ(t.values[0].component, -1);
  EXPECT_EQ(t.values[0].precision, 2);
  EXPECT_EQ(t.values[1].source, Placeholder::Source::time);
  EXPECT_EQ(t.values[1].precision, 1);
  EXPECT_EQ(t.values[1].conversion, 'f');
}

TEST(TextTemplate, TakesComponentsFormatsAndDottedBodyNames) {
  const TextTemplate t = parsed("{lid.1.angular_velocity.z:.3e}{frame}{cube.velocity.y:.0g}");
  ASSERT_EQ(t.values.size(), 3u);
  EXPECT_EQ(t.values[0].body, 1u);
  EXPECT_EQ(t.values[0].quantity, BodyQuantity::angular_velocity);
  EXPECT_EQ(t.values[0].component, 2);
  EXPECT_EQ(t.values[0].precision, 3);
  EXPECT_EQ(t.values[0].conversion, 'e');
  EXPECT_EQ(t.values[1].source, Placeholder::Source::frame);
  EXPECT_EQ(t.values[2].quantity, BodyQuantity::velocity);
  EXPECT_EQ(t.values[2].component, 1);
  EXPECT_EQ(t.values[2].precision, 0);
  EXPECT_EQ(t.values[2].conversion, 'g');
}

TEST(TextTemplate, DefaultsToTwoDecimals) {
  const TextTemplate t = parsed("{cube.kinetic_energy}");
  ASSERT_EQ(t.values.size(), 1u);
  EXPECT_EQ(t.values[0].precision, 2);
  EXPECT_EQ(t.values[0].conversion, 'f');
}

// Python's mini-language subset [[fill]align][sign][0][width][.N][type].
TEST(TextTemplate, ReadsSignWidthFillAndAlignment) {
  const TextTemplate t = parsed("{time:+8.3f} {time:*^10e} {time: 06.1g} {time:<7} {frame:5d}");
  ASSERT_EQ(t.values.size(), 5u);
  EXPECT_EQ(t.values[0].sign, '+');
  EXPECT_EQ(t.values[0].width, 8);
  EXPECT_EQ(t.values[0].precision, 3);
  EXPECT_EQ(t.values[0].align, '>');
  EXPECT_EQ(t.values[1].fill, '*');
  EXPECT_EQ(t.values[1].align, '^');
  EXPECT_EQ(t.values[1].conversion, 'e');
  EXPECT_EQ(t.values[2].sign, ' ');
  EXPECT_EQ(t.values[2].fill, '0');
  EXPECT_EQ(t.values[2].align, '=');
  EXPECT_EQ(t.values[2].width, 6);
  EXPECT_EQ(t.values[3].align, '<');
  EXPECT_EQ(t.values[3].width, 7);
  EXPECT_EQ(t.values[3].precision, 2);  // the defaults: .2f
  EXPECT_EQ(t.values[3].conversion, 'f');
  EXPECT_EQ(t.values[4].width, 5);
}

TEST(TextTemplate, DoubledBracesAreLiteralBraces) {
  const TextTemplate t = parsed("{{x}} = {time}}}");
  ASSERT_EQ(t.values.size(), 1u);
  EXPECT_EQ(t.pieces[0], "{x} = ");
  EXPECT_EQ(t.pieces[1], "}");
}

TEST(TextTemplate, EachMistakeIsAnErrorQuotingThePlaceholder) {
  EXPECT_EQ(error_of("{ball.speed}"), "{ball.speed}: no body is named \"ball\"");
  EXPECT_EQ(error_of("{cbe.angular_velocity}"), "{cbe.angular_velocity}: no body is named \"cbe\"");
  EXPECT_NE(error_of("{cube.spin}").find("{cube.spin}: unknown quantity"), std::string::npos);
  EXPECT_NE(error_of("{temperature}").find("expected time, frame or BODY.QUANTITY"),
            std::string::npos);
  EXPECT_EQ(error_of("{cube.speed.x}"),
            "{cube.speed.x}: speed is a number, it has no component .x");
  EXPECT_NE(error_of("{time:5d}").find("unknown format \":5d\""), std::string::npos);
  EXPECT_NE(error_of("{time:.18f}").find("unknown format"), std::string::npos);
  EXPECT_NE(error_of("t = {time").find("without its"), std::string::npos);
  EXPECT_NE(error_of("{frame:.2f}")
                .find("{frame:.2f}: unknown format \":.2f\" (expected "
                      "[[fill]align][sign][0][width][d]: frame is a whole"),
            std::string::npos);
  EXPECT_NE(error_of("{time:+41.2f}").find("width up to 40"), std::string::npos);
  EXPECT_NE(error_of("{time:+8.3q}").find("unknown format"), std::string::npos);
  EXPECT_NE(error_of("{time:8.3f!}").find("unknown format"), std::string::npos);
  EXPECT_NE(error_of("{time:.f}").find("unknown format"), std::string::npos);
  EXPECT_NE(error_of("a } b").find("lone"), std::string::npos);
}

TEST(TextTemplate, NamesEveryQuantity) {
  for (const BodyQuantity q : {BodyQuantity::position, BodyQuantity::velocity, BodyQuantity::speed,
                               BodyQuantity::angular_velocity, BodyQuantity::angular_speed,
                               BodyQuantity::angular_momentum, BodyQuantity::kinetic_energy}) {
    const TextTemplate t = parsed("{cube." + std::string(quantity_name(q)) + "}");
    ASSERT_EQ(t.values.size(), 1u);
    EXPECT_EQ(t.values[0].quantity, q);
  }
}

// Joints are named as bodies are: {JOINT.angle} of a hinge, {JOINT.speed} of a hinge, a slider or
// a distance, {JOINT.force} of any, with components; what a kind lacks is refused by name.
TEST(TextTemplate, ReadsAJointsAngleSpeedAndForce) {
  const std::vector<JointName> joints = {{"door", physics::JointKind::hinge},
                                         {"rod", physics::JointKind::distance},
                                         {"pin", physics::JointKind::ball}};
  const Result<TextTemplate> t = parse_text_template(
      "{door.angle:.3f} {rod.speed} {pin.force.y:.1f} {cube.speed}", kBodies, joints);
  ASSERT_TRUE(t) << t.error();
  ASSERT_EQ(t->values.size(), 4u);
  EXPECT_EQ(t->values[0].source, Placeholder::Source::joint);
  EXPECT_EQ(t->values[0].joint, 0u);
  EXPECT_EQ(t->values[0].joint_quantity, JointQuantity::angle);
  EXPECT_EQ(t->values[0].precision, 3);
  EXPECT_EQ(t->values[1].joint, 1u);
  EXPECT_EQ(t->values[1].joint_quantity, JointQuantity::speed);
  EXPECT_EQ(t->values[2].joint, 2u);
  EXPECT_EQ(t->values[2].joint_quantity, JointQuantity::force);
  EXPECT_EQ(t->values[2].component, 1);
  EXPECT_EQ(t->values[3].source, Placeholder::Source::body);
  const auto error = [&](std::string_view text) {
    const Result<TextTemplate> out = parse_text_template(text, kBodies, joints);
    return out ? std::string() : out.error();
  };
  EXPECT_EQ(error("{rod.angle}"),
            "{rod.angle}: only a hinge has an angle (\"rod\" is a distance joint)");
  EXPECT_EQ(error("{pin.speed}"),
            "{pin.speed}: a hinge, a slider or a distance has a speed (\"pin\" is a ball joint)");
  EXPECT_EQ(error("{door.angle.x}"), "{door.angle.x}: angle is a number, it has no component");
  EXPECT_EQ(error("{door.torque}"),
            "{door.torque}: unknown quantity of joint \"door\" (expected angle, speed or force)");
}

}  // namespace
}  // namespace tumble::scene
