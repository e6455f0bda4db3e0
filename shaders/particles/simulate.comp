#version 460
#define PARTICLE_WRITES_STATE
// particles-simulate: one fixed step for every slot. A slot whose turn it is spawns a particle
// (spawn id k lives in slot k % capacity; the rate is capacity / max lifetime, so the slot's last
// particle is dead by then); a living particle moves under gravity, buoyancy, curl-noise
// turbulence and drag; a particle whose age reaches its lifetime, or that crosses a killing
// floor, dies. Each slot depends only on itself: the result is the same whatever the thread order.
#include "common/finite.glsl"
#include "particles/curl_noise.glsl"
#include "particles/particle_data.glsl"
#include "particles/random.glsl"

layout(local_size_x = 64) in;
layout(push_constant) uniform StepBlock {
  ParticleStepPush stepPush;
};

const float kTwoPi = 6.28318530718;

vec3 spawnPosition(uint seed, uint id) {
  vec3 origin = system.emitter.xyz;
  float radius = system.emitter.w;
  uint shape = system.modes.x;
  if (shape == kEmitterDisc) {
    float r = radius * sqrt(random01(seed, id, 0u));
    float angle = kTwoPi * random01(seed, id, 1u);
    return origin + vec3(r * cos(angle), 0.0, r * sin(angle));
  }
  if (shape == kEmitterSphere) {
    float z = 2.0 * random01(seed, id, 0u) - 1.0;
    float angle = kTwoPi * random01(seed, id, 1u);
    float r = radius * pow(random01(seed, id, 2u), 1.0 / 3.0);
    return origin + r * vec3(sqrt(max(1.0 - z * z, 0.0)) * vec2(cos(angle), sin(angle)), z);
  }
  return origin;
}

// Uniform over the cone of directions around system.direction with half-angle acos(direction.w).
vec3 launchDirection(uint seed, uint id) {
  vec3 axis = system.direction.xyz;
  float cosTheta = mix(1.0, system.direction.w, random01(seed, id, 3u));
  float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  float phi = kTwoPi * random01(seed, id, 4u);
  vec3 helper = abs(axis.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 tangent = normalize(cross(helper, axis));
  vec3 bitangent = cross(axis, tangent);
  return axis * cosTheta + (tangent * cos(phi) + bitangent * sin(phi)) * sinTheta;
}

Particle spawn(uint id) {
  uint seed = system.modes.w;
  Particle p;
  float speed = mix(system.speedLifetime.x, system.speedLifetime.y, random01(seed, id, 5u));
  float lifetime = mix(system.speedLifetime.z, system.speedLifetime.w, random01(seed, id, 6u));
  p.positionAge = vec4(spawnPosition(seed, id), 0.0);
  p.velocityLifetime = vec4(launchDirection(seed, id) * speed, lifetime);
  vec4 v = system.variation;
  p.attributes =
      vec4(1.0 + v.x * (2.0 * random01(seed, id, 7u) - 1.0), kTwoPi * random01(seed, id, 8u),
           v.z * (2.0 * random01(seed, id, 9u) - 1.0), 1.0 + v.y * (2.0 * random01(seed, id, 10u) - 1.0));
  return p;
}

// Semi-implicit Euler over dt: forces at the start of the step, then the new velocity moves it.
void advance(inout Particle p, float dt, float time) {
  if (dt <= 0.0) return;
  vec3 position = p.positionAge.xyz;
  float age = p.positionAge.w;
  vec3 acceleration = system.gravity.xyz + vec3(0.0, system.forces.y * (1.0 - lifeFraction(p)), 0.0);
  if (system.forces.z > 0.0)
    acceleration += system.forces.z * curlNoise(position * system.forces.w, time * system.gravity.w);
  vec3 velocity = (p.velocityLifetime.xyz + acceleration * dt) * exp(-system.forces.x * dt);
  position += velocity * dt;
  age += dt;
  float floorHeight = system.blend.y;
  if (system.modes.y != kFloorNone && position.y < floorHeight) {
    if (system.modes.y == kFloorKill) {
      age = p.velocityLifetime.w;
    } else if (velocity.y < 0.0) {
      float restitution = system.variation.w;
      position.y = floorHeight + (floorHeight - position.y) * restitution;
      velocity.y = -velocity.y * restitution;
    }
  }
  if (anyNotFinite(position)) age = p.velocityLifetime.w;
  p.positionAge = vec4(position, age);
  p.velocityLifetime.xyz = velocity;
  p.attributes.y += p.attributes.z * dt;
}

void main() {
  uint slot = gl_GlobalInvocationID.x;
  uint capacity = system.modes.z;
  if (slot >= capacity) return;
  float dt = stepPush.time.x;
  uint offset = (slot + capacity - stepPush.spawn.x) % capacity;  // position in this step's spawns
  Particle p;
  if (offset < stepPush.spawn.y) {
    // Born during the step: it lives only the rest of it, so a high rate gives an even stream
    // rather than one puff per step.
    float born = stepPush.time.w + float(offset) * stepPush.time.z;
    p = spawn(stepPush.spawn.z + offset);
    advance(p, dt - min(born, dt), stepPush.time.y + born);
  } else {
    p = particles[slot];
    if (!isAlive(p)) return;
    advance(p, dt, stepPush.time.y);
  }
  particles[slot] = p;
}
