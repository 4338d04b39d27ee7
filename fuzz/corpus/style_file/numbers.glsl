/* tlab style
name = "numbers"
description = "a float of seven digits, a wide int and a bool"
properties = ["color"]

[[parameter]]
name = "a"
type = "float"
default = 0.1234567
range = [-1.5e3, 0.1234567]
description = "a float"

[[parameter]]
name = "n"
type = "int"
default = -7
range = [-2147483648, 2147483647]
description = "an int"

[[parameter]]
name = "b"
type = "bool"
default = true
description = "a bool"
*/
vec4 composite() { return vec4(a, float(n), b ? 1.0 : 0.0, 1.0); }
