#version 330 core
in vec3 vViewPos;
in vec3 vViewNormal;
layout(location = 0) out vec4 outPosition;  // view space, metres; w = 1 where there is geometry
layout(location = 1) out vec4 outNormal;    // view space, unit
void main()
{
    outPosition = vec4(vViewPos, 1.0);
    outNormal = vec4(normalize(vViewNormal), 1.0);
}
